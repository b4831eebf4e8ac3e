#include "controlrow.h"

#include "bitswitches.h"
#include "bus/bus.h"
#include "models/livevaluesmodel.h"
#include "bus/valuetext.h"
#include "models/devicetitle.h"
#include "models/writecommand.h"
#include "protocol/valuecodec.h"
#include "protocol/valueformat.h"
#include "flowlayout.h"
#include "theme.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleValidator>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>

namespace jumo {

namespace {

QString translatedLabel(const QString &label)
{
    return QCoreApplication::translate("jumo::maps", label.toUtf8().constData());
}

// Writes that change what the device drives ask first.
bool changesOutputs(const RegisterEntry &e)
{
    static const QStringList controls{"analog_output", "digital_output", "external_input", "binary_outputs",
                                      "switches", "command", "override", "alpha"};
    return controls.contains(e.control);
}

} // namespace

ControlRow::ControlRow(Bus *bus, int device, const RegisterMap &map, const RegisterEntry &entry, LiveValuesModel *values,
                       QWidget *parent)
    : QWidget(parent), m_bus(bus), m_device(device), m_map(map), m_entry(entry), m_values(values),
      m_command(new WriteCommand(bus, device, entry.id, this)), m_current(new QLabel(this)), m_state(new QLabel(this))
{
    setObjectName(QStringLiteral("control_") + entry.id);
    m_state->setObjectName(QStringLiteral("state_") + entry.id);
    m_state->setWordWrap(true);
    auto *layout = new QGridLayout(this);
    layout->setContentsMargins(0, 2, 0 , 2);
    auto *title = new QLabel(QStringLiteral("<b>%1</b> <span style='color:gray'>%2</span>")
                                     .arg(translatedLabel(entry.label).toHtmlEscaped(), formatAddress(entry.address)),
                             this);
    title->setWordWrap(true);
    layout->addWidget(title, 0, 0, 1, 3);
    QStringList hints;
    if (!entry.precondition.isEmpty())
        hints << tr("Precondition: %1").arg(translatedLabel(entry.precondition));
    if (entry.storage == Storage::Eeprom)
        hints << tr("Stored in EEPROM: about 10,000 write cycles, write only when needed.");
    else if (entry.storage == Storage::Ram)
        hints << tr("Stored in RAM: lost when the device is switched off.");
    if (!hints.isEmpty()) {
        auto *hint = new QLabel(hints.join(QLatin1Char('\n')), this);
        hint->setWordWrap(true);
        Theme::colourText(hint, Theme::Role::Hint);
        layout->addWidget(hint, 1, 0, 1, 3);
    }

    // Command buttons flow onto as many rows as the page's width needs.
    auto *commands = new FlowLayout;
    auto *inputs = new QHBoxLayout;
    if (entry.type == ValueType::Bitfield && entry.control == QLatin1String("command")) {
        for (const BitDefinition &b : entry.bits) {
            if (b.reserved || (entry.activationMask && b.mask() == *entry.activationMask) || b.width != 1)
                continue;
            auto *button = new QPushButton(translatedLabel(b.label), this);
            button->setObjectName(QStringLiteral("command_%1_%2").arg(entry.id, b.id));
            connect(button, &QPushButton::clicked, this, [this, b] {
                write(b.id, translatedLabel(b.label), tr("send the command \"%1\"").arg(translatedLabel(b.label)));
            });
            commands->addWidget(button);
            m_buttons << button;
        }
    } else if (entry.type == ValueType::Bitfield) {
        m_switches = new BitSwitches(bus, device, map, entry, this);
        connect(m_switches, &BitSwitches::switchRequested, this, &ControlRow::switchBit);
        inputs->addWidget(m_switches, 1);
    } else if (entry.type == ValueType::Bool || entry.type == ValueType::Enum) {
        m_choice = new QComboBox(this);
        if (entry.type == ValueType::Bool) {
            m_choice->addItem(tr("Off"), QStringLiteral("0"));
            m_choice->addItem(tr("On"), QStringLiteral("1"));
        } else {
            for (auto it = entry.enumValues.cbegin(); it != entry.enumValues.cend(); ++it)
                m_choice->addItem(translatedLabel(it.value()), QString::number(it.key()));
        }
        inputs->addWidget(m_choice);
    } else {
        m_edit = new QLineEdit(this);
        m_edit->setObjectName(QStringLiteral("input_") + entry.id);
        QString range;
        if (entry.minimum || entry.maximum)
            range = tr("%1 to %2").arg(entry.minimum ? ValueFormat::limit(*entry.minimum, entry) : QStringLiteral("..."),
                                       entry.maximum ? ValueFormat::limit(*entry.maximum, entry) : QStringLiteral("..."));
        m_edit->setPlaceholderText(range.isEmpty() ? entry.unit : ValueFormat::joinUnit(range, entry.unit));
        connect(m_edit, &QLineEdit::returnPressed, this, &ControlRow::writeInput);
        inputs->addWidget(m_edit);
        auto *unit = new QLabel(ValueText::unit(entry), this);
        unit->setObjectName(QStringLiteral("unit_") + entry.id);
        unit->setToolTip(ValueText::unitNote(entry, map));
        inputs->addWidget(unit);
    }
    if (m_buttons.isEmpty() && !(m_switches && m_switches->switchesSingleBits())) {
        m_writeButton = new QPushButton(m_switches ? tr("Write all bits") : tr("Write"), this);
        m_writeButton->setObjectName(QStringLiteral("write_") + entry.id);
        connect(m_writeButton, &QPushButton::clicked, this, &ControlRow::writeInput);
        inputs->addWidget(m_writeButton);
    }
    if (entry.restoreValue) {
        m_restoreButton = new QPushButton(tr("Back to the device's own value"), this);
        m_restoreButton->setObjectName(QStringLiteral("restore_") + entry.id);
        connect(m_restoreButton, &QPushButton::clicked, this, [this] {
            write(ValueCodec::formatFloat(*m_entry.restoreValue), tr("the device's own value"),
                  tr("hand %1 back to the device").arg(translatedLabel(m_entry.label)));
        });
        inputs->addWidget(m_restoreButton);
    }
    inputs->addStretch();
    if (m_buttons.isEmpty()) {
        delete commands;
        layout->addLayout(inputs, 2, 0, 1, 3);
    } else {
        layout->addLayout(commands, 2, 0, 1, 3);
        delete inputs;
    }
    // The device's value and the last write's state each get the row's whole width.
    m_current->setWordWrap(true);
    layout->addWidget(m_current, 3, 0, 1, 3);
    layout->addWidget(m_state, 4, 0, 1, 3);
    m_state->hide();   // until there is a write to speak of
    layout->setColumnStretch(2, 1);

    connect(m_command, &WriteCommand::stateChanged, this,
            [this](WriteCommand::State state, const QString &message) { showWriteState(int(state), message); });
    if (m_values) {
        connect(m_values, &QAbstractItemModel::dataChanged, this, &ControlRow::refreshCurrent);
        refreshCurrent();
    }
}

void ControlRow::showWriteState(int state, const QString &message)
{
    switch (WriteCommand::State(state)) {
    case WriteCommand::State::Pending:
        Theme::colourText(m_state, Theme::Role::Pending);
        m_state->setText(tr("Pending: %1").arg(message));
        break;
    case WriteCommand::State::Confirmed:
        Theme::colourText(m_state, Theme::Role::Confirmed);
        m_state->setText(tr("Confirmed: %1").arg(message));
        break;
    case WriteCommand::State::Refused:
        Theme::colourText(m_state, Theme::Role::Refused);
        m_state->setText(tr("Refused: %1").arg(message));
        break;
    case WriteCommand::State::Unknown:
        // Neither done nor refused: only the device can tell, and nothing is resent.
        Theme::colourText(m_state, Theme::Role::Unknown, QStringLiteral("font-weight: bold"));
        m_state->setText(tr("Unknown, check the device: %1").arg(message));
        break;
    case WriteCommand::State::Idle:
        m_state->clear();
        break;
    }
    m_state->setVisible(!m_state->text().isEmpty());
    if (m_switches)
        m_switches->setBusy(WriteCommand::State(state) == WriteCommand::State::Pending);
    if (m_values)
        refreshCurrent();
}

void ControlRow::refreshCurrent()
{
    if (!isVisible()) {
        m_dirty = true;   // caught up in showEvent()
        return;
    }
    m_dirty = false;
    if (m_switches)
        m_switches->refresh();
    if (m_values->rowOf(m_entry.id) < 0) {
        if (m_switches && m_switches->switchesSingleBits())
            m_current->setText(tr("Write-only: the lamps show the states the device reports elsewhere."));
        else
            m_current->setText(m_entry.isReadable() ? QString() : tr("Write-only: the device cannot report it."));
        return;
    }
    // The value a write just read back is the device's value now (the polls catch up).
    if (const DecodedValue *readBack = m_command->newerReadBack(); readBack && !m_switches) {
        m_current->setText(tr("Device: %1").arg(ValueFormat::withUnit(*readBack, m_entry)));
        Theme::plain(m_current);
        return;
    }
    // The value only while it is current; otherwise no number, or a stale one, and why.
    const EntryState *state = m_bus->entryState(m_device, m_entry.id);
    const bool current = state && state->isCurrent();
    // Switches show their bits on their lamps; the word itself only says why it is not current.
    QString text = m_switches && m_switches->switchesSingleBits() ? QString()
                                                                  : tr("Device: %1").arg(ValueText::value(state, m_entry));
    if (!current)
        text += QStringLiteral(" (%1)").arg(ValueText::status(state, m_map, m_bus->clockMs()));
    m_current->setText(text.trimmed());
    if (current)
        Theme::plain(m_current);
    else
        Theme::colourText(m_current, Theme::Role::Hint, QStringLiteral("font-style: italic"));
}

void ControlRow::setReadOnly(bool readOnly)
{
    m_readOnly = readOnly;
    for (QWidget *w : findChildren<QWidget *>()) {
        if (qobject_cast<QLineEdit *>(w) || qobject_cast<QComboBox *>(w) || qobject_cast<QPushButton *>(w))
            w->setEnabled(!readOnly);
    }
    if (m_switches)
        m_switches->setReadOnly(readOnly);
    setToolTip(readOnly ? tr("Read-only mode: nothing is written to the devices.") : QString());
}

QString ControlRow::inputValue() const
{
    if (m_edit)
        return m_edit->text().trimmed();
    if (m_choice)
        return m_choice->currentData().toString();
    if (m_switches && !m_switches->switchesSingleBits())
        return m_switches->tickedValue();
    return {};
}

void ControlRow::setInputValue(const QString &value)
{
    if (m_edit)
        m_edit->setText(value);
    if (m_choice)
        m_choice->setCurrentIndex(std::max(0, m_choice->findData(value)));
    if (m_switches)
        m_switches->setTicked(value);
}

QString ControlRow::stateText() const
{
    return m_state->text();
}

void ControlRow::writeInput()
{
    QString value = inputValue();
    if (value.isEmpty())
        return;
    QString shown = value;
    if (m_choice) {
        shown = m_choice->currentText();
    } else if (m_switches) {
        // The bits by their labels, as the question and the outcome name them.
        QStringList labels;
        for (const QString &id : value.split(QLatin1Char('+'), Qt::SkipEmptyParts)) {
            if (const BitDefinition *b = m_entry.bitById(id))
                labels << translatedLabel(b->label);
        }
        shown = labels.isEmpty() ? tr("every bit off") : tr("on: %1").arg(labels.join(QStringLiteral(", ")));
    }
    // A float as the locale writes it ("42,5"), or with a dot; the codec takes a dot.
    if (m_edit && m_entry.type == ValueType::Float) {
        const std::optional<QString> number = ValueFormat::parseNumber(value);
        if (!number) {
            // Never handed on as typed: the codec would read "1.500" as 1.5.
            refuse(tr("'%1' is no number that can be read one way only; write it without thousands separators")
                           .arg(value));
            return;
        }
        value = *number;
        // The question names the value that goes out, not the text it was read from.
        QLocale locale;
        locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);
        shown = locale.toString(value.toDouble(), 'g', QLocale::FloatingPointShortest);
    }
    if (m_edit)
        shown = ValueFormat::joinUnit(shown, m_entry.unit);
    write(value, shown, tr("write %1 = %2").arg(translatedLabel(m_entry.label), shown));
}

void ControlRow::refuse(const QString &reason)
{
    Theme::colourText(m_state, Theme::Role::Refused);
    m_state->setText(tr("Not written: %1").arg(reason));
    m_state->show();
}

bool ControlRow::confirm(const QString &description) const
{
    const bool drives = changesOutputs(m_entry);
    const bool wears = m_entry.storage == Storage::Eeprom;
    if (!drives && !wears)
        return true;
    // The question names the device: a page left open on one device while thinking of
    // another must not switch the wrong one.
    const QString device = m_deviceTitle.isEmpty() ? DeviceTitle::full(m_map, m_bus->deviceAddress(m_device), QString())
                                                   : m_deviceTitle;
    QStringList text{tr("Do you want to %1?").arg(description), tr("Device: %1").arg(device)};
    if (drives)
        text << tr("This changes what the device drives.");
    if (wears)
        text << tr("The value is stored in EEPROM, which lasts about 10,000 writes.");
    // A modal question only ever answers an action the user just started. No is the
    // default: an Enter meant for the field never changes a device.
    QMessageBox box(QMessageBox::Question, tr("Confirm write"), text.join(QLatin1Char('\n')),
                    QMessageBox::Yes | QMessageBox::No, window());
    box.setObjectName(QStringLiteral("confirmWrite"));
    box.setDefaultButton(QMessageBox::No);
    return box.exec() == QMessageBox::Yes;
}

void ControlRow::write(const QString &value, const QString &shown, const QString &description)
{
    // In read-only mode the controls are disabled; a write that still comes here goes to
    // the bus, which refuses it, so the refusal shows here and in the audit log.
    // Check before asking: a value the device would refuse never gets a confirmation.
    const EncodeResult check = ValueCodec::encode(m_entry, m_map, value);
    if (!check.ok()) {
        refuse(check.error);
        return;
    }
    if (!m_readOnly && !confirm(description))
        return;
    m_command->write(value, shown);
}

void ControlRow::switchBit(const QString &bitId, bool on)
{
    const BitDefinition *bit = m_entry.bitById(bitId);
    if (!bit)
        return;
    const QString label = translatedLabel(bit->label);
    if (!m_readOnly
        && !confirm(on ? tr("switch \"%1\" on").arg(label) : tr("switch \"%1\" off").arg(label)))
        return;
    m_command->writeBits({{bitId, on}}, on ? tr("%1 on").arg(label) : tr("%1 off").arg(label));
}

void ControlRow::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    if (m_dirty)
        refreshCurrent();
}

} // namespace jumo
