#include "bitswitches.h"

#include "ledindicator.h"
#include "models/bitstates.h"
#include "protocol/bitwrite.h"
#include "theme.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>

namespace jumo {

namespace {

QString translatedLabel(const QString &label)
{
    return QCoreApplication::translate("jumo::maps", label.toUtf8().constData());
}

} // namespace

BitSwitches::BitSwitches(const Bus *bus, DeviceId device, const RegisterMap &map, const RegisterEntry &entry,
                         QWidget *parent)
    : QWidget(parent), m_bus(bus), m_device(device), m_entry(entry), m_single(BitWrite::canSwitchBits(map, entry))
{
    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setHorizontalSpacing(6);
    const QList<const BitDefinition *> bits = BitWrite::switchableBits(entry);
    if (!m_single) {
        int i = 0;
        for (const BitDefinition *b : bits) {
            auto *box = new QCheckBox(translatedLabel(b->label), this);
            box->setObjectName(QStringLiteral("bit_%1_%2").arg(entry.id, b->id));
            box->setProperty("bitId", b->id);
            grid->addWidget(box, i / 3, i % 3);
            m_boxes << box;
            ++i;
        }
        auto *hint = new QLabel(tr("The device does not report these bits: a write sets every bit as ticked here."),
                                this);
        hint->setWordWrap(true);
        Theme::colourText(hint, Theme::Role::Hint);
        grid->addWidget(hint, (i + 2) / 3, 0, 1, 3);
        return;
    }
    // Two bits a line: lamp with label, On, Off.
    const int perLine = 2;
    int i = 0;
    for (const BitDefinition *b : bits) {
        const int row = i / perLine;
        const int column = (i % perLine) * 4;
        auto *led = new LedIndicator(translatedLabel(b->label), LedIndicator::Kind::Status, this);
        led->setObjectName(QStringLiteral("switch_%1_%2").arg(entry.id, b->id));
        auto *on = new QPushButton(tr("On"), this);
        auto *off = new QPushButton(tr("Off"), this);
        on->setObjectName(QStringLiteral("on_%1_%2").arg(entry.id, b->id));
        off->setObjectName(QStringLiteral("off_%1_%2").arg(entry.id, b->id));
        for (QPushButton *button : {on, off})
            button->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
        connect(on, &QPushButton::clicked, this, [this, id = b->id] { emit switchRequested(id, true); });
        connect(off, &QPushButton::clicked, this, [this, id = b->id] { emit switchRequested(id, false); });
        grid->addWidget(led, row, column);
        grid->addWidget(on, row, column + 1);
        grid->addWidget(off, row, column + 2);
        grid->setColumnMinimumWidth(column + 3, 18);
        m_leds.insert(b->id, led);
        m_onButtons.insert(b->id, on);
        m_offButtons.insert(b->id, off);
        ++i;
    }
    grid->setColumnStretch(perLine * 4, 1);   // the switches stay by their lamps
    refresh();
}

void BitSwitches::refresh()
{
    if (!m_single)
        return;
    for (const BitStateReading &r : readBitStates(*m_bus, m_device, m_entry)) {
        LedIndicator *led = m_leds.value(r.bit->id);
        if (!led)
            continue;
        led->setState(r.state == AlarmBitsModel::BitState::On    ? LedIndicator::State::On
                      : r.state == AlarmBitsModel::BitState::Off ? LedIndicator::State::Off
                                                                 : LedIndicator::State::Unknown,
                      r.validity == Validity::Stale);
        const QString state = r.state == AlarmBitsModel::BitState::Unknown ? tr("unknown: the device cannot be read")
                : r.validity == Validity::Stale                            ? tr("stale")
                : r.state == AlarmBitsModel::BitState::On                  ? tr("on")
                                                                           : tr("off");
        led->setToolTip(tr("Bit %1 of %2, %3; reported in %4").arg(r.bit->bit).arg(formatAddress(m_entry.address), state,
                                                                          r.reportedIn));
    }
    updateEnabled();
}

void BitSwitches::setBusy(bool busy)
{
    m_busy = busy;
    updateEnabled();
}

void BitSwitches::setReadOnly(bool readOnly)
{
    m_readOnly = readOnly;
    updateEnabled();
}

void BitSwitches::updateEnabled()
{
    for (QCheckBox *box : std::as_const(m_boxes))
        box->setEnabled(!m_readOnly);
    for (auto it = m_leds.cbegin(); it != m_leds.cend(); ++it) {
        // A switch already in the asked state needs no write; an unknown one can be set
        // either way.
        const LedIndicator *led = it.value();
        const bool known = led->state() != LedIndicator::State::Unknown && !led->isStale();
        const bool free = !m_readOnly && !m_busy;
        m_onButtons.value(it.key())->setEnabled(free && !(known && led->isOn()));
        m_offButtons.value(it.key())->setEnabled(free && !(known && !led->isOn()));
    }
}

QString BitSwitches::tickedValue() const
{
    QStringList on;
    for (QCheckBox *box : m_boxes) {
        if (box->isChecked())
            on << box->property("bitId").toString();
    }
    return on.isEmpty() ? QStringLiteral("0") : on.join(QLatin1Char('+'));
}

void BitSwitches::setTicked(const QString &value)
{
    const QStringList on = value.split(QLatin1Char('+'));
    for (QCheckBox *box : std::as_const(m_boxes))
        box->setChecked(on.contains(box->property("bitId").toString()));
}

} // namespace jumo
