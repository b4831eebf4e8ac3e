#include "sim/simulateddevice.h"

#include <QLoggingCategory>
#include <QSet>
#include <QtEndian>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

Q_LOGGING_CATEGORY(lcSim, "jumo.sim", QtWarningMsg)

namespace jumo {

namespace {

constexpr quint8 IllegalFunction = 0x01;
constexpr quint8 IllegalDataAddress = 0x02;
constexpr quint8 WriteProtected = 0x08;

quint16 readWord(const QByteArray &data, int offset)
{
    return quint16(quint8(data[offset]) << 8 | quint8(data[offset + 1]));
}

void appendWord(QByteArray &data, quint16 word)
{
    data.append(char(word >> 8));
    data.append(char(word & 0xFF));
}

} // namespace

SimulatedDevice::SimulatedDevice(std::shared_ptr<const RegisterMap> map, quint8 address, QObject *parent)
    : QObject(parent), m_map(std::move(map)), m_address(address), m_random(quint32(address) * 7919u + 17u)
{
    for (const RegisterEntry &e : m_map->entries()) {
        if (!e.alias.isEmpty())
            continue;
        for (int a = e.address; a <= e.lastAddress(); ++a)
            m_words.insert(quint16(a), 0);
    }
    if (!m_map->simulation)
        return;
    for (auto it = m_map->simulation->initial.cbegin(); it != m_map->simulation->initial.cend(); ++it) {
        const RegisterEntry *e = m_map->entry(it.key());
        if (e && e->type == ValueType::Text)
            setText(it.key(), it.value().toString());
        else
            setNumber(it.key(), it.value().toDouble());
    }
    updateLimits();
}

QByteArray SimulatedDevice::exception(quint8 function, quint8 code) const
{
    QByteArray pdu;
    pdu.append(char(function | 0x80));
    pdu.append(char(code));
    return pdu;
}

QByteArray SimulatedDevice::process(const QByteArray &pdu, bool broadcast)
{
    if (pdu.isEmpty())
        return {};
    const quint8 function = quint8(pdu[0]);
    QByteArray reply;
    switch (function) {
    case 0x03:
    case 0x04: {
        if (pdu.size() != 5)
            return {};   // malformed: a real device stays silent
        const quint16 count = readWord(pdu, 3);
        if (count == 0 || broadcast)
            return {};   // the manuals: no answer to a read of zero words, nor to a broadcast
        reply = readRegisters(function, readWord(pdu, 1), count);
        break;
    }
    case 0x06:
        if (pdu.size() != 5)
            return {};
        reply = writeRegisters(function, readWord(pdu, 1), {readWord(pdu, 3)}, broadcast);
        break;
    case 0x10: {
        if (pdu.size() < 6)
            return {};
        const quint16 count = readWord(pdu, 3);
        const int bytes = quint8(pdu[5]);
        if (bytes != count * 2 || pdu.size() != 6 + bytes)
            return {};
        QList<quint16> values;
        for (int i = 0; i < count; ++i)
            values << readWord(pdu, 6 + 2 * i);
        reply = writeRegisters(function, readWord(pdu, 1), values, broadcast);
        break;
    }
    default:
        reply = exception(function, IllegalFunction);
        break;
    }
    return broadcast ? QByteArray() : reply;
}

QByteArray SimulatedDevice::readRegisters(quint8 function, quint16 start, quint16 count) const
{
    if (count > m_map->protocol.effectiveMaxReadWords() || int(start) + count > 0x10000)
        return exception(function, IllegalDataAddress);
    for (int a = start; a < start + count; ++a) {
        const RegisterEntry *e = m_map->entryAt(quint16(a));
        if (!e || !e->isReadable())
            return exception(function, IllegalDataAddress);
    }
    QByteArray reply;
    reply.append(char(function));
    reply.append(char(count * 2));
    for (int a = start; a < start + count; ++a) {
        quint16 w = m_words.value(quint16(a));
        const RegisterEntry *e = m_map->entryAt(quint16(a));
        const auto forced = m_forced.constFind(e->id);
        if (forced != m_forced.cend() && e->type == ValueType::Float) {
            const float error = *forced == ValueStatus::Underrange ? -std::numeric_limits<float>::infinity()
                    : *forced == ValueStatus::Overrange              ? std::numeric_limits<float>::infinity()
                                                                     : std::bit_cast<float>(0x7FC00000u);
            w = ValueCodec::encodeFloat(error, m_map->protocol.floatWordOrder).at(a - e->address);
        }
        appendWord(reply, w);
    }
    return reply;
}

QByteArray SimulatedDevice::writeRegisters(quint8 function, quint16 start, const QList<quint16> &values, bool broadcast)
{
    const int count = int(values.size());
    if (count < 1 || count > m_map->protocol.effectiveMaxWriteWords() || int(start) + count > 0x10000)
        return exception(function, IllegalDataAddress);
    for (int a = start; a < start + count; ++a) {
        const RegisterEntry *e = m_map->entryAt(quint16(a));
        if (!e)
            return exception(function, IllegalDataAddress);
        if (!e->isWritable())
            return exception(function, WriteProtected);
    }
    for (int i = 0; i < count; ++i)
        m_words.insert(quint16(start + i), values[i]);
    qCDebug(lcSim) << "device" << m_address << (broadcast ? "broadcast write" : "write") << formatAddress(start) << count;
    afterWrite(start, quint16(count));
    emit registersWritten(start, quint16(count));

    QByteArray reply;
    reply.append(char(function));
    appendWord(reply, start);
    if (function == 0x06)
        appendWord(reply, values.first());
    else
        appendWord(reply, quint16(count));
    return reply;
}

void SimulatedDevice::afterWrite(quint16 start, quint16 count)
{
    const SimulationSpec *sim = m_map->simulation ? &*m_map->simulation : nullptr;
    QSet<QString> touched;
    for (int a = start; a < start + count;) {
        const RegisterEntry *e = m_map->entryAt(quint16(a));
        a = e->lastAddress() + 1;
        touched.insert(e->id);
        if (e->type == ValueType::Bitfield) {
            applyCommands(*e, m_words.value(e->address));
            // A write-only word sets the signals its bits stand for; the device reports
            // them where the map says.
            for (const BitDefinition &b : e->bits) {
                if (!b.stateFrom.isEmpty() && (!e->activationMask || (m_words.value(e->address) & *e->activationMask))) {
                    setFlag(b.stateFrom, m_words.value(e->address) & b.mask());
                    touched.insert(b.stateFrom.section(QLatin1Char('.'), 0, 0));
                }
            }
        }
        if (!sim)
            continue;
        if (e->id == sim->binding("setpointOverride") || e->id == sim->binding("processValueOverride")) {
            const double v = number(e->id);
            if (e->restoreValue && v == *e->restoreValue)
                m_overrides.remove(e->id);
            else
                m_overrides.insert(e->id, v);
        }
    }
    if (!sim)
        return;
    for (const auto &[first, second] : sim->links) {
        if (touched.contains(first.section(QLatin1Char('.'), 0, 0)))
            setFlag(second, flag(first));
        else if (touched.contains(second.section(QLatin1Char('.'), 0, 0)))
            setFlag(first, flag(second));
    }
}

void SimulatedDevice::applyCommands(const RegisterEntry &entry, quint16 value)
{
    if (entry.activationMask && (value & *entry.activationMask) != *entry.activationMask)
        return;   // without the activation bit the device ignores the word
    const SimulationSpec *sim = m_map->simulation ? &*m_map->simulation : nullptr;
    if (sim && entry.id == sim->binding("binaryOutputControl")) {
        const QString outputs = sim->binding("binaryOutputs");
        const RegisterEntry *status = m_map->entry(outputs);
        if (status) {
            quint16 on = 0;
            for (const BitDefinition &b : entry.bits) {
                if (b.kind == BitKind::Command && (!entry.activationMask || b.mask() != *entry.activationMask))
                    on |= quint16(value & b.mask());
            }
            m_words.insert(status->address, on);
        }
        return;
    }
    if (!sim)
        return;
    for (const BitDefinition &b : entry.bits) {
        if (!(value & b.mask()))
            continue;
        const QString action = sim->commands.value(entry.id + QLatin1Char('.') + b.id);
        if (action == QLatin1String("manual_on")) {
            m_manual = true;
        } else if (action == QLatin1String("manual_off")) {
            m_manual = false;
            m_controllerOff = false;
        } else if (action == QLatin1String("tuning_start")) {
            m_tuning = true;
            m_tuningSeconds = 0;
        } else if (action == QLatin1String("tuning_abort")) {
            m_tuning = false;
        } else if (action == QLatin1String("controller_off")) {
            m_controllerOff = true;
        }
    }
    if (sim->status.contains(QStringLiteral("manual")))
        setFlag(sim->status.value(QStringLiteral("manual")), m_manual);
    if (sim->status.contains(QStringLiteral("tuning")))
        setFlag(sim->status.value(QStringLiteral("tuning")), m_tuning);
}

void SimulatedDevice::storeWords(const RegisterEntry &entry, const QList<quint16> &words)
{
    for (int i = 0; i < words.size(); ++i)
        m_words.insert(quint16(entry.address + i), words[i]);
}

bool SimulatedDevice::setNumber(const QString &id, double value)
{
    const RegisterEntry *e = m_map->entry(id);
    if (!e)
        return false;
    switch (e->type) {
    case ValueType::Float:
        storeWords(*e, ValueCodec::encodeFloat(float(value), m_map->protocol.floatWordOrder));
        return true;
    case ValueType::Int32:
    case ValueType::UInt32:
        storeWords(*e, ValueCodec::splitWords(quint32(qint64(std::llround(value))), m_map->protocol.int32WordOrder));
        return true;
    case ValueType::Text:
        return false;
    default:
        storeWords(*e, {quint16(qint64(std::llround(value)))});
        return true;
    }
}

bool SimulatedDevice::setWords(quint16 address, const QList<quint16> &words)
{
    for (int i = 0; i < words.size(); ++i) {
        if (!m_words.contains(quint16(address + i)))
            return false;
    }
    for (int i = 0; i < words.size(); ++i)
        m_words.insert(quint16(address + i), words[i]);
    return true;
}

bool SimulatedDevice::setText(const QString &id, const QString &text)
{
    const RegisterEntry *e = m_map->entry(id);
    if (!e || e->type != ValueType::Text)
        return false;
    QByteArray bytes = text.toLatin1().left(e->textBytes - 1);
    bytes.resize(e->wordCount() * 2, '\0');
    QList<quint16> words;
    for (int i = 0; i < bytes.size(); i += 2)
        words << quint16(quint8(bytes[i]) << 8 | quint8(bytes[i + 1]));
    storeWords(*e, words);
    return true;
}

double SimulatedDevice::number(const QString &id) const
{
    const RegisterEntry *e = m_map->entry(id);
    if (!e || e->type == ValueType::Text)
        return 0;
    QList<quint16> words;
    for (int a = e->address; a <= e->lastAddress(); ++a)
        words << m_words.value(quint16(a));
    const DecodedValue v = ValueCodec::decode(*e, *m_map, words);
    return v.value.toDouble();
}

bool SimulatedDevice::setFlag(const QString &reference, bool on)
{
    if (!setOneFlag(reference, on))
        return false;
    // The same state reported twice (a bool word and a bit of a status word): both agree,
    // as on the device.
    if (m_map->simulation) {
        for (const auto &[first, second] : m_map->simulation->links) {
            if (first == reference)
                setOneFlag(second, on);
            else if (second == reference)
                setOneFlag(first, on);
        }
    }
    return true;
}

bool SimulatedDevice::setOneFlag(const QString &reference, bool on)
{
    const RegisterEntry *e = m_map->entry(reference.section(QLatin1Char('.'), 0, 0));
    if (!e)
        return false;
    const QString bitId = reference.section(QLatin1Char('.'), 1);
    if (bitId.isEmpty()) {
        m_words.insert(e->address, on ? 1 : 0);
        return true;
    }
    const BitDefinition *b = e->bitById(bitId);
    if (!b)
        return false;
    quint16 w = m_words.value(e->address);
    w = on ? quint16(w | b->mask()) : quint16(w & ~b->mask());
    m_words.insert(e->address, w);
    return true;
}

bool SimulatedDevice::flag(const QString &reference) const
{
    const RegisterEntry *e = m_map->entry(reference.section(QLatin1Char('.'), 0, 0));
    if (!e)
        return false;
    const QString bitId = reference.section(QLatin1Char('.'), 1);
    if (bitId.isEmpty())
        return m_words.value(e->address) != 0;
    const BitDefinition *b = e->bitById(bitId);
    return b && (m_words.value(e->address) & b->mask());
}

bool SimulatedDevice::forceStatus(const QString &id, ValueStatus status)
{
    const RegisterEntry *e = m_map->entry(id);
    if (!e || e->type != ValueType::Float)
        return false;
    if (status == ValueStatus::Ok)
        m_forced.remove(id);
    else
        m_forced.insert(id, status);
    return true;
}

double SimulatedDevice::noise(double amplitude)
{
    return (m_random.generateDouble() * 2.0 - 1.0) * amplitude;
}

double SimulatedDevice::bound(const QString &role) const
{
    return number(m_map->simulation->binding(role));
}

void SimulatedDevice::setBound(const QString &role, double value)
{
    const QString id = m_map->simulation->binding(role);
    if (!id.isEmpty())
        setNumber(id, value);
}

void SimulatedDevice::advance(double seconds)
{
    if (!m_map->simulation || seconds <= 0)
        return;
    if (m_map->simulation->model == QLatin1String("power_controller"))
        advancePowerController(seconds);
    else
        advanceProcessController(seconds);
    updateLimits();
}

void SimulatedDevice::advancePowerController(double seconds)
{
    const double setpoint = std::clamp(bound(QStringLiteral("setpoint")), 0.0, 100.0);
    const double mains = 230.0 + noise(0.5);
    const double level = setpoint;
    const double resistance = std::max(0.1, bound(QStringLiteral("loadResistance")));
    const double voltage = mains * level / 100.0 + noise(0.05);
    const double current = std::max(0.0, voltage / resistance + noise(0.01));
    setBound(QStringLiteral("effectiveSetpoint"), setpoint);
    setBound(QStringLiteral("outputLevel"), level);
    setBound(QStringLiteral("actualValue"), level);
    setBound(QStringLiteral("loadVoltage"), voltage);
    setBound(QStringLiteral("loadCurrent"), current);
    setBound(QStringLiteral("power"), voltage * current);
    setBound(QStringLiteral("mainsVoltage"), mains);
    setBound(QStringLiteral("mainsFrequency"), 50.0 + noise(0.02));
    setBound(QStringLiteral("alpha"), 180.0 * (1.0 - level / 100.0));
    // The heat sink warms with the power and cools towards 30 °C, time constant 60 s.
    const double previous = bound(QStringLiteral("temperature"));
    const double target = 30.0 + voltage * current / 400.0;
    const double temperature = (previous == 0 ? 30.0 : previous) + (target - previous) * (1.0 - std::exp(-seconds / 60.0));
    setBound(QStringLiteral("temperature"), temperature);
    setBound(QStringLiteral("temperatureF"), temperature * 9.0 / 5.0 + 32.0);
}

void SimulatedDevice::advanceProcessController(double seconds)
{
    const QString spOverride = m_map->simulation->binding(QStringLiteral("setpointOverride"));
    const QString pvOverride = m_map->simulation->binding(QStringLiteral("processValueOverride"));
    const double setpoint = m_overrides.contains(spOverride) ? m_overrides.value(spOverride)
                                                             : bound(QStringLiteral("setpoint"));
    double pv = bound(QStringLiteral("processValue"));
    const double ambient = 20.0;
    double output = std::clamp(4.0 * (setpoint - pv), -100.0, 100.0);
    double target = setpoint;
    if (m_controllerOff) {
        output = 0;
        target = ambient;
    } else if (m_manual) {
        output = 30.0;
        target = ambient + 3.0 * output;
    }
    // First-order lag, time constant 8 s, plus a little measurement noise.
    pv += (target - pv) * (1.0 - std::exp(-seconds / 8.0));
    const double measured = m_overrides.contains(pvOverride) ? m_overrides.value(pvOverride) : pv + noise(0.05);
    setBound(QStringLiteral("processValue"), pv);
    setBound(QStringLiteral("processValueUnfiltered"), measured);
    setBound(QStringLiteral("displayValue"), measured);
    setBound(QStringLiteral("output"), output);
    setBound(QStringLiteral("outputHeating"), std::max(0.0, output));
    setBound(QStringLiteral("outputCooling"), std::min(0.0, output));
    setBound(QStringLiteral("deviation"), setpoint - measured);
    setBound(QStringLiteral("rampEnd"), setpoint);
    if (m_tuning) {
        m_tuningSeconds += seconds;
        if (m_tuningSeconds > 20.0) {
            m_tuning = false;
            if (m_map->simulation->status.contains(QStringLiteral("tuning")))
                setFlag(m_map->simulation->status.value(QStringLiteral("tuning")), false);
        }
    }
}

void SimulatedDevice::updateLimits()
{
    if (!m_map->simulation)
        return;
    // A bit listed by several limits is on when any of them is exceeded.
    QHash<QString, bool> flags;
    for (const SimulationLimit &limit : m_map->simulation->limits) {
        bool exceeded = false;
        if (!m_forced.contains(limit.value)) {
            const double v = number(limit.value);
            const double threshold = limit.thresholdId.isEmpty() ? limit.threshold : number(limit.thresholdId);
            exceeded = limit.above ? v > threshold : v < threshold;
        }
        for (const QString &reference : limit.set)
            flags[reference] = flags.value(reference) || exceeded;
    }
    for (auto it = flags.cbegin(); it != flags.cend(); ++it)
        setFlag(it.key(), it.value());
}

} // namespace jumo
