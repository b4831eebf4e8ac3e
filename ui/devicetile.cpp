#include "devicetile.h"

#include "models/alarmbitsmodel.h"
#include "models/devicetitle.h"
#include "models/livevaluesmodel.h"
#include "bus/valuetext.h"
#include "protocol/registermap.h"
#include "protocol/valueformat.h"

#include <QCoreApplication>
#include <QEvent>
#include <QKeyEvent>
#include <QLocale>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>

namespace jumo {

namespace {

QString mapText(const QString &text)
{
    return QCoreApplication::translate("jumo::maps", text.toUtf8().constData());
}

// "1:02:03" or "2:03": the time left in a program segment.
QString duration(qint64 seconds)
{
    const qint64 s = std::max<qint64>(0, seconds);
    if (s >= 3600)
        return QStringLiteral("%1:%2:%3").arg(s / 3600).arg(s / 60 % 60, 2, 10, QLatin1Char('0')).arg(s % 60, 2, 10, QLatin1Char('0'));
    return QStringLiteral("%1:%2").arg(s / 60).arg(s % 60, 2, 10, QLatin1Char('0'));
}

constexpr int padding = 8;

} // namespace

DeviceTile::DeviceTile(DeviceId device, const RegisterMap &map, quint8 address, LiveValuesModel *values,
                       AlarmBitsModel *alarms, QWidget *parent)
    : QWidget(parent), m_device(device), m_map(map), m_address(address), m_values(values), m_alarms(alarms)
{
    setObjectName(QStringLiteral("tile_%1_%2").arg(map.family).arg(address));
    setCursor(Qt::PointingHandCursor);
    setFocusPolicy(Qt::StrongFocus);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    m_title = DeviceTitle::brief(map, address);
    setAccessibleName(m_title);
    // A poll cycle changes the models block by block: the faceplate catches up once for
    // them all, a moment later (a control room reads it, nobody needs each block).
    m_pending.setSingleShot(true);
    m_pending.setInterval(refreshDelayMs);
    connect(&m_pending, &QTimer::timeout, this, &DeviceTile::refresh);
    auto later = [this] {
        if (!m_pending.isActive())
            m_pending.start();
    };
    connect(m_values, &QAbstractItemModel::dataChanged, this, later);
    connect(m_alarms, &QAbstractItemModel::dataChanged, this, later);
    connect(m_alarms, &AlarmBitsModel::activeAlarmsChanged, this, later);
    connect(m_alarms, &AlarmBitsModel::alarmsKnownChanged, this, later);
    refresh();
}

void DeviceTile::setCondition(const DeviceCondition &condition)
{
    m_condition = condition;
    refresh();
}

void DeviceTile::setDensity(Density density)
{
    if (m_density == density)
        return;
    m_density = density;
    updateGeometry();
    update();
}

std::optional<double> DeviceTile::number(const QString &entryId) const
{
    const int r = m_values->rowOf(entryId);
    if (r < 0)
        return std::nullopt;
    const QVariant v = m_values->index(r, LiveValuesModel::ValueColumn).data(LiveValuesModel::NumericRole);
    if (!v.isValid())
        return std::nullopt;
    // A nominal value kept as an enum ("100 A") counts by the number its text starts with.
    const RegisterEntry *e = m_map.entry(entryId);
    if (e && e->type == ValueType::Enum)
        return leadingNumber(e->enumValues.value(v.toInt()));
    // As the text beside it reads: noise around zero that shows as 0.000 W is zero, and
    // draws no arrow below the scale.
    if (e && e->type == ValueType::Float)
        return ValueFormat::rounded(v.toDouble(), e->precision);
    return v.toDouble();
}

std::optional<bool> DeviceTile::stateOn(const QString &reference) const
{
    const QString id = reference.section(QLatin1Char('.'), 0, 0);
    const std::optional<double> word = number(id);
    if (!word)
        return std::nullopt;
    const QString bitId = reference.section(QLatin1Char('.'), 1);
    if (bitId.isEmpty())
        return *word != 0;
    const RegisterEntry *e = m_map.entry(id);
    const BitDefinition *bit = e ? e->bitById(bitId) : nullptr;
    if (!bit)
        return std::nullopt;
    return (quint32(*word) & bit->mask()) != 0;
}

std::optional<QString> DeviceTile::firstOn(const QList<FaceplateState> &states, const QString &otherwise,
                                           bool *progress) const
{
    for (const FaceplateState &s : states) {
        const std::optional<bool> on = stateOn(s.when);
        if (!on)
            return std::nullopt;   // an earlier state unknown: nobody can say which one holds
        if (*on) {
            if (progress)
                *progress = s.progress;
            return mapText(s.text);
        }
    }
    return mapText(otherwise);
}

DeviceTile::Row DeviceTile::row(const QString &entryId, const QString &label) const
{
    Row row;
    row.label = mapText(label);
    const int r = m_values->rowOf(entryId);
    if (r < 0)
        return row;
    const QModelIndex index = m_values->index(r, LiveValuesModel::ValueColumn);
    const auto validity = Validity(index.data(LiveValuesModel::ValidityRole).toInt());
    row.value = index.data(LiveValuesModel::ValueWithUnitRole).toString();
    row.stale = validity == Validity::Stale;
    row.errorValue = index.data(LiveValuesModel::ErrorValueRole).toBool();
    return row;
}

void DeviceTile::refresh()
{
    m_pending.stop();
    if (!isVisible()) {
        m_dirty = true;   // caught up in showEvent()
        return;
    }
    m_dirty = false;
    const FaceplateSpec &face = m_map.faceplate;
    const bool online = m_condition.isOnline();
    QStringList lines;
    auto addLine = [&lines, this](const Row &r) {
        lines << QStringLiteral("%1: %2").arg(r.label, r.stale ? r.value + QLatin1Char(' ') + tr("(stale)") : r.value);
    };

    m_primary.reset();
    if (!face.primary.isEmpty()) {
        m_primary = row(face.primary, face.primaryLabel);
        addLine(*m_primary);
    }
    m_rows.clear();
    m_barsDrawn = 0;
    m_barsFilled = 0;
    for (const FaceplateValue &v : face.values) {
        Row r = row(v.entry, v.label);
        const RegisterEntry *e = m_map.entry(v.entry);
        const std::optional<double> value = number(v.entry);
        double low = 0;
        std::optional<double> high;
        switch (v.scale) {
        case FaceplateValue::Scale::None:
            break;
        case FaceplateValue::Scale::Range:
            low = v.barMin;
            high = v.barMax;
            r.scaleText = tr("Bar: %1 to %2 %3").arg(QLocale().toString(v.barMin), QLocale().toString(v.barMax), e ? e->unit : QString());
            break;
        case FaceplateValue::Scale::Nominal:
        case FaceplateValue::Scale::Limit: {
            std::optional<double> full = 1.0;
            QString unnumbered;   // a scale entry read, but its value has no number (an enum without a text)
            QString notPositive;  // a part of the scale that is zero or below ("Power limit = -5")
            for (const QString &id : v.scaleFrom) {
                const std::optional<double> part = number(id);
                // Two negative parts make a positive product, and no scale at all.
                if (part && *part <= 0 && notPositive.isEmpty())
                    notPositive = QStringLiteral("%1 = %2").arg(mapText(m_map.entry(id)->label), QLocale().toString(*part, 'g', 6));
                if (!part && unnumbered.isEmpty() && m_values->rowOf(id) >= 0) {
                    const QModelIndex index = m_values->index(m_values->rowOf(id), LiveValuesModel::ValueColumn);
                    if (index.data(LiveValuesModel::NumericRole).isValid())
                        unnumbered = QStringLiteral("%1 = %2").arg(mapText(m_map.entry(id)->label),
                                                                    index.data(LiveValuesModel::NumericRole).toString());
                }
                full = full && part ? std::optional<double>(*full * *part) : std::nullopt;
            }
            const QString amount = full ? QStringLiteral("%1 %2").arg(QLocale().toString(*full, 'g', 6), e ? e->unit : QString()).trimmed()
                                        : QString();
            if (full && notPositive.isEmpty()) {
                high = *full;
                r.scaleText = v.scale == FaceplateValue::Scale::Nominal ? tr("Bar: 0 to %1 (nominal)").arg(amount)
                                                                        : tr("Bar: 0 to %1 (limit set on the device)").arg(amount);
            } else if (full && v.scaleFrom.size() == 1) {
                r.scaleText = tr("No bar: its scale, %1, is not above zero.").arg(amount);
            } else if (full) {
                r.scaleText = tr("No bar: %1, a part of its scale, is not above zero.").arg(notPositive);
            } else if (!unnumbered.isEmpty()) {
                r.scaleText = tr("No bar: the device reports %1, which the map gives no number.").arg(unnumbered);
            } else {
                r.scaleText = tr("No bar: its scale is not known yet.");
            }
            break;
        }
        }
        // A device that is not heard has no bars, not even empty tracks: its rows say why.
        if (online && high && *high > low) {
            r.scaleKnown = true;
            r.zero = low < 0 && *high > 0 ? -low / (*high - low) : 0;
            ++m_barsDrawn;
            // Only a current value has a bar; a stale or unknown one leaves the track empty.
            if (value && !r.stale) {
                const double f = (*value - low) / (*high - low);
                r.beyond = f > 1 || f < 0;
                r.fraction = std::clamp(f, 0.0, 1.0);
                ++m_barsFilled;
            }
        }
        addLine(r);
        m_rows << r;
    }
    m_valuesText = lines.join(QLatin1Char('\n'));

    // The state: condition first, then alarms and warnings among the known words.
    m_stateText = conditionText(m_condition);
    m_alarmText = alarmsText(m_condition, *m_alarms);
    const bool known = m_alarms->alarmsKnown() && online;
    QStringList alarmNames;
    QStringList warningNames;
    for (int i = 0; i < m_alarms->rowCount(); ++i) {
        const QModelIndex index = m_alarms->index(i);
        if (AlarmBitsModel::BitState(index.data(AlarmBitsModel::BitStateRole).toInt()) != AlarmBitsModel::BitState::On)
            continue;
        const auto kind = BitKind(index.data(AlarmBitsModel::KindRole).toInt());
        if (kind == BitKind::Alarm)
            alarmNames << index.data().toString();
        else if (kind == BitKind::Warning)
            warningNames << index.data().toString();
    }
    // An error value (overrange, a broken sensor) is no reading at all: the faceplate
    // says so in its state and names it, as it does a warning.
    QStringList errorValues;
    if (m_primary && m_primary->errorValue)
        errorValues << QStringLiteral("%1: %2").arg(m_primary->label, m_primary->value);
    for (const Row &r : std::as_const(m_rows)) {
        if (r.errorValue)
            errorValues << QStringLiteral("%1: %2").arg(r.label, r.value);
    }
    switch (m_condition.state) {
    case DeviceCondition::State::Disconnected:
        m_summary = Summary::Disconnected;
        break;
    case DeviceCondition::State::Identifying:
        m_summary = Summary::Checking;
        break;
    case DeviceCondition::State::WrongDevice:
        m_summary = Summary::WrongDevice;
        break;
    case DeviceCondition::State::Offline:
        m_summary = Summary::NotAnswering;
        break;
    case DeviceCondition::State::LineLost:
        m_summary = Summary::LineLost;
        break;
    case DeviceCondition::State::Online:
        if (known && !alarmNames.isEmpty())
            m_summary = Summary::Alarm;
        else if ((known && !warningNames.isEmpty()) || !errorValues.isEmpty())
            m_summary = Summary::Warning;
        else if (!known || m_alarms->alarmsStale())
            m_summary = Summary::Uncertain;
        else
            m_summary = Summary::Normal;
        break;
    }
    m_alarmNames.clear();
    if (online && !alarmNames.isEmpty())
        m_alarmNames = alarmNames.join(QStringLiteral(", "));
    else if (online && !(warningNames + errorValues).isEmpty())
        m_alarmNames = (warningNames + errorValues).join(QStringLiteral(", "));
    // Names read from words that have aged are the last known ones, and say so (in
    // place of the count, which says it too).
    m_alarmNamesStale = !m_alarmNames.isEmpty() && m_alarms->alarmsStale();
    if (m_alarmNamesStale)
        m_alarmNames += QLatin1Char(' ') + tr("(stale)");

    m_modeText.clear();
    if (!face.modeOtherwise.isEmpty() || !face.modes.isEmpty()) {
        const std::optional<QString> mode = online ? firstOn(face.modes, face.modeOtherwise) : std::nullopt;
        m_modeText = mode ? *mode : tr("unknown");
    }
    m_programText.clear();
    if (face.hasProgram()) {
        bool progress = true;
        const std::optional<QString> state = online ? firstOn(face.programStates, face.programOtherwise, &progress)
                                                    : std::nullopt;
        const std::optional<double> segment = number(face.programSegment);
        const std::optional<double> segments = number(face.programSegments);
        const std::optional<double> left = number(face.programTimeLeft);
        if (!state) {
            m_programText = tr("unknown");
        } else {
            QStringList parts{*state};
            if (progress && segment && segments)
                parts << tr("segment %1 of %2").arg(qint64(*segment)).arg(qint64(*segments));
            if (progress && left)
                parts << tr("%1 left").arg(duration(qint64(*left)));
            m_programText = parts.join(QStringLiteral(", "));
        }
    }

    QStringList tip{m_title, QStringLiteral("%1 – %2").arg(summaryText(), m_stateText)};
    if (!m_condition.detail.isEmpty())
        tip << m_condition.detail;
    tip << m_valuesText;
    for (const Row &r : std::as_const(m_rows)) {
        if (!r.scaleText.isEmpty())
            tip << QStringLiteral("%1 – %2").arg(r.label, r.scaleText)
                            + (r.beyond ? QLatin1Char(' ') + tr("(beyond the scale)") : QString());
    }
    if (!m_modeText.isEmpty())
        tip << tr("Mode: %1").arg(m_modeText) + (face.modeNote.isEmpty() ? QString() : QLatin1Char('\n') + mapText(face.modeNote));
    if (!m_programText.isEmpty())
        tip << tr("Program: %1").arg(m_programText);
    tip << m_alarmText;
    if (!m_alarmNames.isEmpty())
        tip << m_alarmNames;
    const QString tipText = tip.join(QLatin1Char('\n'));
    if (tipText == toolTip())
        return;   // nothing the faceplate shows has changed
    setToolTip(tipText);
    setAccessibleDescription(tip.mid(1).join(QLatin1Char('\n')));
    update();
}

QString DeviceTile::summaryText(Summary summary)
{
    switch (summary) {
    case Summary::WrongDevice:
        return tr("Wrong device");
    case Summary::LineLost:
        return tr("Line lost");
    case Summary::NotAnswering:
        return tr("Not answering");
    case Summary::Alarm:
        return tr("Alarm");
    case Summary::Warning:
        return tr("Warning");
    case Summary::Uncertain:
        return tr("Alarms unknown");
    case Summary::Normal:
        return tr("Normal");
    case Summary::Checking:
        return tr("Checking");
    case Summary::Disconnected:
        return tr("Disconnected");
    }
    return {};
}

Theme::Role DeviceTile::roleOf(Summary summary)
{
    switch (summary) {
    case Summary::WrongDevice:
        return Theme::Role::TileWrongDevice;
    case Summary::LineLost:
    case Summary::NotAnswering:
        return Theme::Role::TileOffline;
    case Summary::Alarm:
        return Theme::Role::TileAlarm;
    case Summary::Warning:
        return Theme::Role::TileWarning;
    case Summary::Uncertain:
        return Theme::Role::TileUncertain;
    case Summary::Normal:
        return Theme::Role::TileOk;
    case Summary::Checking:
    case Summary::Disconnected:
        return Theme::Role::TileIdle;
    }
    return Theme::Role::TileIdle;
}

QString DeviceTile::conditionText(const DeviceCondition &condition)
{
    const QString since = condition.since.isValid() ? QLocale().toString(condition.since.time(), QStringLiteral("HH:mm:ss"))
                                                    : QString();
    switch (condition.state) {
    case DeviceCondition::State::Online:
        return tr("Online");
    case DeviceCondition::State::Offline:
        return tr("Not answering since %1").arg(since);
    case DeviceCondition::State::LineLost:
        return tr("Line lost since %1").arg(since);
    case DeviceCondition::State::Disconnected:
        return tr("Line disconnected");
    case DeviceCondition::State::Identifying:
        return tr("Checking identity");
    case DeviceCondition::State::WrongDevice:
        return tr("Wrong device since %1").arg(since);
    }
    return {};
}

QString DeviceTile::alarmsText(const DeviceCondition &condition, const AlarmBitsModel &alarms)
{
    // "No alarm" only when every alarm word is known; otherwise nobody can say.
    const bool known = alarms.alarmsKnown() && condition.isOnline();
    QString text = known ? tr("%n active alarm(s)", nullptr, alarms.activeAlarms()) : tr("Alarms unknown");
    if (known && alarms.alarmsStale())
        text += QLatin1Char(' ') + tr("(stale)");
    return text;
}

QFont DeviceTile::baseFontFor(double scale) const
{
    QFont f = font();
    if (scale == 1)
        return f;
    if (f.pointSizeF() > 0)
        f.setPointSizeF(f.pointSizeF() * scale);
    else
        f.setPixelSize(int(f.pixelSize() * scale + 0.5));
    return f;
}

int DeviceTile::lineHeightFor(Density density, double scale) const
{
    return QFontMetrics(baseFontFor(scale)).height() + int((density == Density::Compact ? 1 : 4) * scale + 0.5);
}

QFont DeviceTile::bigFontFor(Density density, double scale) const
{
    QFont big = baseFontFor(scale);
    big.setPointSizeF(big.pointSizeF() * (density == Density::Compact ? 1.6 : 2.0));
    big.setBold(true);
    return big;
}

QSize DeviceTile::sizeHintFor(Density density, double scale) const
{
    const FaceplateSpec &face = m_map.faceplate;
    // The title, the values, the mode (or the condition while the device does not
    // answer), the program, the alarms.
    int lines = 3 + int(face.values.size());
    if (face.hasProgram())
        ++lines;
    int height = lines * lineHeightFor(density, scale) + 2 * padding;
    if (!face.primary.isEmpty())
        height += QFontMetrics(bigFontFor(density, scale)).height() + 2;
    return {int((density == Density::Compact ? 236 : 300) * scale), height};
}

QSize DeviceTile::minimumSizeHint() const
{
    return {int((m_density == Density::Compact ? 200 : 240) * m_scale), sizeHint().height()};
}

void DeviceTile::setScale(double scale)
{
    if (m_scale == scale)
        return;
    m_scale = scale;
    updateGeometry();
    update();
}

void DeviceTile::drawShape(QPainter &painter, const QRectF &box) const
{
    // Each state has a shape of its own, so it reads without colour: a circle with a tick
    // (normal), a triangle (warning), an octagon (alarm), a dashed circle (not answering),
    // a dashed square with a cross (line lost), a double square (wrong device), a hollow
    // circle (idle, checking) and a circle with a question mark (alarms unknown).
    const QColor ink = Theme::color(Theme::Role::TileText);
    QPen pen(ink, 1.5);
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    const QRectF r = box.adjusted(1.5, 1.5, -1.5, -1.5);
    const QPointF c = r.center();
    const qreal w = r.width();
    auto mark = [&](const QString &text) {
        QFont f = baseFont();
        f.setBold(true);
        f.setPixelSize(std::max(7, int(w * 0.7)));
        painter.setFont(f);
        painter.setPen(ink);
        painter.drawText(r, Qt::AlignCenter, text);
    };
    switch (m_summary) {
    case Summary::Normal: {
        painter.setPen(pen);
        painter.setBrush(Theme::color(Theme::Role::LedStatus));
        painter.drawEllipse(r);
        QPainterPath tick;
        tick.moveTo(c.x() - w * 0.25, c.y());
        tick.lineTo(c.x() - w * 0.05, c.y() + w * 0.2);
        tick.lineTo(c.x() + w * 0.28, c.y() - w * 0.22);
        painter.setPen(QPen(ink, 2));
        painter.setBrush(Qt::NoBrush);
        painter.drawPath(tick);
        break;
    }
    case Summary::Warning: {
        painter.setPen(pen);
        painter.setBrush(Theme::color(Theme::Role::LedWarning));
        painter.drawPolygon(QPolygonF{QPointF(c.x(), r.top()), r.bottomRight(), r.bottomLeft()});
        mark(QStringLiteral("!"));
        break;
    }
    case Summary::Alarm: {
        painter.setPen(pen);
        painter.setBrush(Theme::color(Theme::Role::LedAlarm));
        const qreal k = w * 0.29;
        painter.drawPolygon(QPolygonF{{r.left() + k, r.top()}, {r.right() - k, r.top()}, {r.right(), r.top() + k},
                                      {r.right(), r.bottom() - k}, {r.right() - k, r.bottom()}, {r.left() + k, r.bottom()},
                                      {r.left(), r.bottom() - k}, {r.left(), r.top() + k}});
        mark(QStringLiteral("!"));
        break;
    }
    case Summary::NotAnswering:
        pen.setStyle(Qt::DashLine);
        painter.setPen(pen);
        painter.setBrush(Qt::NoBrush);
        painter.drawEllipse(r);
        mark(QStringLiteral("?"));
        break;
    case Summary::LineLost:
        pen.setStyle(Qt::DashLine);
        painter.setPen(pen);
        painter.setBrush(Qt::NoBrush);
        painter.drawRect(r);
        painter.setPen(QPen(ink, 2));
        painter.drawLine(r.topLeft() + QPointF(w * 0.25, w * 0.25), r.bottomRight() - QPointF(w * 0.25, w * 0.25));
        painter.drawLine(r.topRight() + QPointF(-w * 0.25, w * 0.25), r.bottomLeft() + QPointF(w * 0.25, -w * 0.25));
        break;
    case Summary::WrongDevice:
        painter.setPen(pen);
        painter.setBrush(Qt::NoBrush);
        painter.drawRect(r);
        painter.drawRect(r.adjusted(3, 3, -3, -3));
        break;
    case Summary::Uncertain:
        painter.setPen(pen);
        painter.setBrush(Qt::NoBrush);
        painter.drawEllipse(r);
        mark(QStringLiteral("?"));
        break;
    case Summary::Checking:
    case Summary::Disconnected:
        painter.setPen(pen);
        painter.setBrush(Qt::NoBrush);
        painter.drawEllipse(r);
        break;
    }
    painter.restore();
}

void DeviceTile::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    const QColor background = Theme::color(stateRole());
    const QColor ink = Theme::color(Theme::Role::TileText);
    painter.fillRect(rect(), background);

    // The frame: a style of its own per state, plain to see without colour.
    QPen frame(ink);
    switch (m_summary) {
    case Summary::Normal:
        frame.setWidth(1);
        if (Theme::current() != Theme::Kind::HighContrast)
            frame.setColor(QColor(ink.red(), ink.green(), ink.blue(), 90));
        break;
    case Summary::Warning:
        frame.setWidth(3);
        frame.setStyle(Qt::DashDotLine);
        break;
    case Summary::Alarm:
        frame.setWidth(4);
        break;
    case Summary::Uncertain:
        frame.setWidth(2);
        frame.setStyle(Qt::DotLine);
        break;
    case Summary::NotAnswering:
    case Summary::LineLost:
        frame.setWidth(2);
        frame.setStyle(Qt::DashLine);
        break;
    case Summary::Checking:
    case Summary::Disconnected:
        frame.setWidth(1);
        frame.setStyle(Qt::DotLine);
        break;
    case Summary::WrongDevice:
        frame.setWidth(2);
        break;
    }
    const qreal half = frame.widthF() / 2;
    painter.setPen(frame);
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(QRectF(rect()).adjusted(half, half, -half, -half));
    if (m_summary == Summary::WrongDevice)
        painter.drawRect(QRectF(rect()).adjusted(5, 5, -5, -5));
    if (hasFocus()) {
        // The tile with the keyboard focus: a frame in the text colour and the highlight,
        // plain to see on every state's colour.
        painter.setPen(QPen(palette().color(QPalette::Highlight), 3));
        painter.drawRect(QRectF(rect()).adjusted(5.5, 5.5, -5.5, -5.5));
        painter.setPen(QPen(ink, 1, Qt::DotLine));
        painter.drawRect(QRectF(rect()).adjusted(7.5, 7.5, -7.5, -7.5));
    }

    const int lh = lineHeight();
    const QRect area = rect().adjusted(padding + 2, padding, -padding - 2, -padding);
    int y = area.top();
    QFont normal = baseFont();
    QFont bold = normal;
    bold.setBold(true);
    const QFontMetrics fm(normal);
    const QFontMetrics boldFm(bold);
    painter.setPen(ink);

    // Title left, the state (shape and word) right.
    const QString word = summaryText();
    const int shape = fm.height() - 2;
    const int wordWidth = boldFm.horizontalAdvance(word);
    const int badgeWidth = shape + 4 + wordWidth;
    const QRect titleRect(area.left(), y, area.width() - badgeWidth - 8, lh);
    painter.setFont(bold);
    painter.drawText(titleRect, Qt::AlignLeft | Qt::AlignVCenter, boldFm.elidedText(m_title, Qt::ElideRight, titleRect.width()));
    drawShape(painter, QRectF(area.right() - badgeWidth + 1, y + (lh - shape) / 2.0, shape, shape));
    painter.setFont(bold);
    painter.setPen(ink);
    painter.drawText(QRect(area.right() - wordWidth + 1, y, wordWidth, lh), Qt::AlignRight | Qt::AlignVCenter, word);
    y += lh;

    auto valueText = [this](const Row &r) { return r.stale ? r.value + QLatin1Char(' ') + tr("(stale)") : r.value; };
    if (m_primary) {
        const QFont big = bigFont();
        const QFontMetrics bigFm(big);
        const int h = bigFm.height() + 2;
        const QString value = valueText(*m_primary);
        QFont valueFont = big;
        valueFont.setItalic(m_primary->stale);
        painter.setFont(valueFont);
        const int valueWidth = std::min(area.width(), QFontMetrics(valueFont).horizontalAdvance(value) + 3);
        painter.drawText(QRect(area.right() - valueWidth + 1, y, valueWidth, h), Qt::AlignRight | Qt::AlignVCenter,
                         QFontMetrics(valueFont).elidedText(value, Qt::ElideRight, area.width()));
        painter.setFont(normal);
        const int labelWidth = area.width() - valueWidth - 6;
        if (labelWidth > 20)
            painter.drawText(QRect(area.left(), y, labelWidth, h), Qt::AlignLeft | Qt::AlignVCenter,
                             fm.elidedText(m_primary->label, Qt::ElideRight, labelWidth));
        y += h;
    }

    // Rows: label, value, and the bar where the map gives one a scale.
    bool anyBar = false;
    for (const FaceplateValue &v : m_map.faceplate.values)
        anyBar = anyBar || v.scale != FaceplateValue::Scale::None;
    const int barWidth = anyBar ? area.width() * 30 / 100 : 0;
    const int textWidth = area.width() - (anyBar ? barWidth + 8 : 0);
    for (qsizetype i = 0; i < m_rows.size(); ++i) {
        const Row &r = m_rows.at(i);
        const QString value = valueText(r);
        QFont valueFont = bold;
        valueFont.setItalic(r.stale);
        const QFontMetrics valueFm(valueFont);
        // A few pixels to spare: the advance is rounded, and a value must not lose a digit.
        const int valueWidth = std::min(textWidth, valueFm.horizontalAdvance(value) + 3);
        painter.setFont(valueFont);
        painter.drawText(QRect(area.left() + textWidth - valueWidth, y, valueWidth, lh), Qt::AlignRight | Qt::AlignVCenter,
                         valueFm.elidedText(value, Qt::ElideRight, valueWidth));
        painter.setFont(normal);
        const int labelWidth = textWidth - valueWidth - 6;
        if (labelWidth > 12)
            painter.drawText(QRect(area.left(), y, labelWidth, lh), Qt::AlignLeft | Qt::AlignVCenter,
                             fm.elidedText(r.label, Qt::ElideRight, labelWidth));
        const FaceplateValue &spec = m_map.faceplate.values.at(i);
        if (spec.scale != FaceplateValue::Scale::None) {
            const QRectF track(area.right() - barWidth + 1, y + lh * 0.25, barWidth, lh * 0.5);
            if (r.scaleKnown) {
                painter.setPen(QPen(QColor(ink.red(), ink.green(), ink.blue(), 150), 1));
                painter.setBrush(Theme::color(Theme::Role::BarTrack));
                painter.drawRect(track);
                if (r.fraction) {
                    const qreal from = track.left() + track.width() * std::min(r.zero, *r.fraction);
                    const qreal to = track.left() + track.width() * std::max(r.zero, *r.fraction);
                    painter.fillRect(QRectF(from, track.top() + 1, std::max<qreal>(1.5, to - from), track.height() - 1),
                                     Theme::color(Theme::Role::BarFill));
                    if (r.beyond) {
                        // Beyond its scale: the track gets a heavy outline and an arrow head
                        // pointing out of the end the value has passed, in the tile's colour
                        // where it lies on the fill, else in the text colour, so it stands out
                        // from what is under it (an ink arrow on the fill merged with the outline).
                        painter.setPen(QPen(ink, 2));
                        painter.setBrush(Qt::NoBrush);
                        painter.drawRect(track);
                        const bool high = *r.fraction >= 1;
                        const QRectF inner = track.adjusted(2, 2, -2, -2);
                        const qreal x = high ? inner.right() : inner.left();
                        const qreal d = (high ? -1 : 1) * std::max<qreal>(4, inner.height() * 1.2);
                        painter.save();
                        painter.setRenderHint(QPainter::Antialiasing);
                        painter.setPen(Qt::NoPen);
                        painter.setBrush(high || r.zero > 0 ? background : ink);
                        painter.drawPolygon(QPolygonF{QPointF(x, inner.center().y()), QPointF(x + d, inner.top()),
                                                      QPointF(x + d, inner.bottom())});
                        painter.restore();
                    }
                    if (r.zero > 0) {
                        painter.setPen(QPen(ink, 1));
                        const qreal zx = track.left() + track.width() * r.zero;
                        painter.drawLine(QPointF(zx, track.top() - 2), QPointF(zx, track.bottom() + 2));
                    }
                }
            }
            painter.setPen(ink);
        }
        y += lh;
    }

    // The mode, or the condition while the device does not answer; the program; alarms.
    painter.setFont(normal);
    if (!m_condition.isOnline()) {
        painter.setFont(bold);
        painter.drawText(QRect(area.left(), y, area.width(), lh), Qt::AlignLeft | Qt::AlignVCenter,
                         boldFm.elidedText(m_stateText, Qt::ElideRight, area.width()));
        painter.setFont(normal);
    } else if (!m_modeText.isEmpty()) {
        painter.drawText(QRect(area.left(), y, area.width(), lh), Qt::AlignLeft | Qt::AlignVCenter,
                         fm.elidedText(tr("Mode: %1").arg(m_modeText), Qt::ElideRight, area.width()));
    }
    y += lh;
    if (m_map.faceplate.hasProgram()) {
        painter.drawText(QRect(area.left(), y, area.width(), lh), Qt::AlignLeft | Qt::AlignVCenter,
                         fm.elidedText(tr("Program: %1").arg(m_programText), Qt::ElideRight, area.width()));
        y += lh;
    }
    const QString alarmLine = m_alarmNames.isEmpty() ? m_alarmText : m_alarmNames;
    QFont alarmFont = m_alarmNames.isEmpty() ? normal : bold;
    alarmFont.setItalic(m_alarmNamesStale);   // as stale values are
    painter.setFont(alarmFont);
    painter.drawText(QRect(area.left(), y, area.width(), lh), Qt::AlignLeft | Qt::AlignVCenter,
                     QFontMetrics(alarmFont).elidedText(alarmLine, Qt::ElideRight, area.width()));
}

void DeviceTile::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange || event->type() == QEvent::PaletteChange)
        updateGeometry();
}

void DeviceTile::mouseReleaseEvent(QMouseEvent *event)
{
    QWidget::mouseReleaseEvent(event);
    emit activated(m_device);
}

void DeviceTile::keyPressEvent(QKeyEvent *event)
{
    switch (event->key()) {
    case Qt::Key_Return:
    case Qt::Key_Enter:
    case Qt::Key_Space:
        emit activated(m_device);
        return;
    default:
        QWidget::keyPressEvent(event);
    }
}

void DeviceTile::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    // Its values, not the settings its bars are scaled by (read every minute and at once
    // after a write, as every setting).
    m_values->setShown(this, true, m_map.faceplateEntries(false));
    if (m_dirty)
        refresh();
}

void DeviceTile::hideEvent(QHideEvent *event)
{
    QWidget::hideEvent(event);
    m_values->setShown(this, false);
}

} // namespace jumo
