#include "history/historyrecorder.h"

#include <QDateTime>

#include <algorithm>
#include <cmath>

namespace jumo {

namespace {

SampleState stateOf(const EntryState &state)
{
    if (state.validity == Validity::Current) {
        switch (state.value.status) {
        case ValueStatus::Ok: return SampleState::Ok;
        case ValueStatus::Underrange: return SampleState::Underrange;
        case ValueStatus::Overrange: return SampleState::Overrange;
        case ValueStatus::Invalid:
        case ValueStatus::DecodeError: break;
        }
        return SampleState::Invalid;
    }
    if (state.validity == Validity::Stale)
        return SampleState::Stale;
    switch (state.error) {
    case ReadError::Timeout:
    case ReadError::Mismatch: return SampleState::Timeout;
    case ReadError::Exception: return SampleState::Exception;
    case ReadError::DeviceOffline: return SampleState::Offline;
    case ReadError::LineLost: return SampleState::LineLost;
    case ReadError::LineClosed: return SampleState::Disconnected;
    case ReadError::NotAvailable: return SampleState::Unavailable;
    case ReadError::Unconfirmed: return SampleState::Unconfirmed;
    case ReadError::WrongDevice: return SampleState::WrongDevice;
    case ReadError::None:
    case ReadError::NotRead: break;
    }
    return SampleState::NotRead;
}

// The number as the entry's precision shows it, scaled to an integer.
double atPrecision(double value, const DisplayPrecision &precision, double magnitude)
{
    int decimals = precision.digits;
    if (precision.kind == DisplayPrecision::Kind::Significant)
        decimals = magnitude > 0 ? precision.digits - 1 - int(std::floor(std::log10(magnitude))) : precision.digits;
    return std::round(value * std::pow(10.0, std::clamp(decimals, -30, 30)));
}

} // namespace

HistoryRecorder::HistoryRecorder(HistoryStore *store, QObject *parent) : QObject(parent), m_store(store)
{
    // Often enough that no value waits much past its heartbeat.
    m_heartbeat.setInterval(int(std::clamp<qint64>(store->heartbeatMs() / 4, 1000, 30000)));
    connect(&m_heartbeat, &QTimer::timeout, this, &HistoryRecorder::heartbeat);
    connect(store, &HistoryStore::recordingResumed, this, [this] { recordAll(true); });
}

HistoryRecorder::~HistoryRecorder() = default;

qint64 HistoryRecorder::now() const
{
    return m_clock ? m_clock() : QDateTime::currentMSecsSinceEpoch();
}

void HistoryRecorder::addSource(const DeviceSource *source, const QString &line)
{
    auto added = std::make_unique<Line>();
    added->source = source;
    added->line = line;
    Line *l = added.get();
    added->connections << connect(source, &DeviceSource::entriesUpdated, this,
                                  [this, l](DeviceId id, const QStringList &ids) { recordEntries(*l, id, ids, false); });
    added->connections << connect(source, &QObject::destroyed, this, [this, l] { removeSource(l->source); });
    m_lines.push_back(std::move(added));
    // What the source already knows (a line polled before the recorder came) is recorded now.
    for (DeviceId id : source->devices()) {
        if (const auto map = source->deviceMap(id)) {
            QStringList ids;
            for (const RegisterEntry &e : map->entries())
                ids << e.id;
            recordEntries(*l, id, ids, false);
        }
    }
    if (!m_heartbeat.isActive())
        m_heartbeat.start();
}

void HistoryRecorder::removeSource(const DeviceSource *source)
{
    for (auto it = m_lines.begin(); it != m_lines.end(); ++it) {
        if ((*it)->source != source && !(source == nullptr && (*it)->source.isNull()))
            continue;
        for (const QMetaObject::Connection &c : std::as_const((*it)->connections))
            disconnect(c);
        m_lines.erase(it);
        break;
    }
    if (m_lines.empty())
        m_heartbeat.stop();
}

HistorySample HistoryRecorder::sampleOf(const RegisterEntry &entry, const EntryState &state)
{
    HistorySample s;
    s.state = stateOf(state);
    if (!hasValue(s.state))
        return s;
    const QVariant &v = state.value.value;
    if (entry.type == ValueType::Text)
        s.text = v.toString();
    else if (v.isValid())
        s.value = v.toDouble();
    else
        s.state = SampleState::Invalid;   // a value that did not decode has no number to keep
    return s;
}

bool HistoryRecorder::differs(const RegisterEntry &entry, const HistorySample &a, const HistorySample &b)
{
    if (a.state != b.state || a.text != b.text)
        return true;
    const bool nanA = std::isnan(a.value);
    const bool nanB = std::isnan(b.value);
    if (nanA || nanB)
        return nanA != nanB;
    if (entry.type != ValueType::Float)
        return a.value != b.value;
    const double magnitude = std::max(std::abs(a.value), std::abs(b.value));
    return atPrecision(a.value, entry.precision, magnitude) != atPrecision(b.value, entry.precision, magnitude);
}

void HistoryRecorder::recordEntries(Line &line, DeviceId id, const QStringList &entryIds, bool force)
{
    const DeviceSource *source = line.source;
    if (!source)
        return;
    const std::shared_ptr<const RegisterMap> map = source->deviceMap(id);
    if (!map)
        return;
    const qint64 time = now();
    QHash<QString, Recorded> &device = line.recorded[id];
    QString deviceName;
    for (const QString &entryId : entryIds) {
        const RegisterEntry *entry = map->entry(entryId);
        const EntryState *state = source->entryState(id, entryId);
        if (!entry || !state || entry->reserved)
            continue;
        HistorySample sample = sampleOf(*entry, *state);
        // Not read yet: nothing to keep before the first poll says something.
        if (sample.state == SampleState::NotRead && !device.contains(entryId))
            continue;
        Recorded &r = device[entryId];
        if (r.series < 0) {
            if (deviceName.isEmpty())
                deviceName = source->deviceName(id);
            HistorySeriesInfo info;
            info.key = {m_store->station(), line.line, deviceName};
            info.entry = entryId;
            info.numeric = isNumeric(entry->type);
            info.unit = entry->unit;
            r.series = m_store->series(info);
        }
        if (!force && r.valid && !differs(*entry, r.last, sample))
            continue;
        sample.series = r.series;
        sample.timeMs = time;
        m_store->record(sample);
        r.last = sample;
        r.valid = true;
        ++m_recorded;
    }
}

void HistoryRecorder::recordAll(bool force)
{
    for (const auto &line : m_lines) {
        const DeviceSource *source = line->source;
        if (!source)
            continue;
        for (auto device = line->recorded.cbegin(); device != line->recorded.cend(); ++device)
            recordEntries(*line, device.key(), device->keys(), force);
    }
}

void HistoryRecorder::heartbeat()
{
    const qint64 due = now() - m_store->heartbeatMs();
    for (const auto &line : m_lines) {
        for (auto device = line->recorded.cbegin(); device != line->recorded.cend(); ++device) {
            QStringList stays;
            for (auto r = device->cbegin(); r != device->cend(); ++r) {
                // A gap needs no repeating: it lasts until something else is recorded.
                if (r->valid && r->last.timeMs <= due && !isGap(r->last.state))
                    stays << r.key();
            }
            if (!stays.isEmpty())
                recordEntries(*line, device.key(), stays, true);
        }
    }
}

} // namespace jumo
