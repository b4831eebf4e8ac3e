#include "history/sqlhistorystore.h"

#include "history/historyreader.h"
#include "history/historywriter.h"

namespace jumo {

SqlHistoryStore::SqlHistoryStore(const HistoryLocation &location, const QString &station,
                                 const HistorySettings &settings, QObject *parent)
    : HistoryStore(parent), m_location(location), m_station(station), m_settings(settings)
{
    m_writerThread.setObjectName(QStringLiteral("jumo-history-writer"));
    m_readerThread.setObjectName(QStringLiteral("jumo-history-reader"));
    m_batchTimer.setInterval(m_settings.batchIntervalMs);
    connect(&m_batchTimer, &QTimer::timeout, this, &SqlHistoryStore::flush);
}

SqlHistoryStore::~SqlHistoryStore()
{
    if (!m_started)
        return;
    m_batchTimer.stop();
    flush();
    QMetaObject::invokeMethod(m_writer, &HistoryWriter::finish, Qt::QueuedConnection);
    m_writerThread.wait();
    delete m_writer;
    QMetaObject::invokeMethod(m_readerContext, [this] { m_reader.reset(); }, Qt::BlockingQueuedConnection);
    m_readerThread.quit();
    m_readerThread.wait();
    delete m_readerContext;
}

void SqlHistoryStore::start()
{
    if (m_started)
        return;
    m_started = true;
    m_writer = new HistoryWriter(m_location, m_station, m_settings);
    m_writer->moveToThread(&m_writerThread);
    connect(m_writer, &HistoryWriter::failed, this, &SqlHistoryStore::onFailed);
    connect(m_writer, &HistoryWriter::resumed, this, &SqlHistoryStore::onResumed);
    connect(m_writer, &HistoryWriter::written, this, &SqlHistoryStore::written);
    connect(m_writer, &HistoryWriter::maintained, this, &SqlHistoryStore::maintained);
    m_writerThread.start();
    QMetaObject::invokeMethod(m_writer, &HistoryWriter::start, Qt::QueuedConnection);
    m_readerContext = new QObject;
    m_readerContext->moveToThread(&m_readerThread);
    m_readerThread.start();
    m_batchTimer.start();
}

int SqlHistoryStore::series(const HistorySeriesInfo &info)
{
    const QString name = info.key.name() + QLatin1Char('/') + info.entry;
    if (const auto known = m_handles.constFind(name); known != m_handles.cend())
        return *known;
    const int handle = int(m_handles.size());
    m_handles.insert(name, handle);
    // Queued before any sample of it, so the writer knows it when the first one comes.
    start();
    QMetaObject::invokeMethod(m_writer, [writer = m_writer, handle, info] { writer->addSeries(handle, info); },
                              Qt::QueuedConnection);
    return handle;
}

void SqlHistoryStore::record(const HistorySample &sample)
{
    if (!m_recording || sample.series < 0 || sample.series >= m_handles.size())
        return;
    HistorySample s = sample;
    // The key of a sample is its series and time: a later sample never replaces one before.
    if (const auto last = m_lastMs.constFind(s.series); last != m_lastMs.cend() && s.timeMs <= *last)
        s.timeMs = *last + 1;
    m_lastMs.insert(s.series, s.timeMs);
    m_pending.append(s);
    if (m_pending.size() >= m_settings.maxBatchSamples)
        flush();
}

void SqlHistoryStore::flush()
{
    if (m_pending.isEmpty() || !m_writer)
        return;
    QMetaObject::invokeMethod(m_writer, [writer = m_writer, samples = std::move(m_pending)] { writer->write(samples); },
                              Qt::QueuedConnection);
    m_pending = {};
}

void SqlHistoryStore::maintainNow()
{
    start();
    flush();
    QMetaObject::invokeMethod(m_writer, &HistoryWriter::maintain, Qt::QueuedConnection);
}

quint64 SqlHistoryStore::requestSamples(const HistoryQuery &query)
{
    const quint64 request = m_nextRequest++;
    start();
    flush();
    QMetaObject::invokeMethod(
            m_readerContext,
            [this, request, query] {
                if (!m_reader)
                    m_reader = std::make_shared<HistoryReader>(m_location);
                const HistoryTrace trace = m_reader->samples(query);
                QMetaObject::invokeMethod(this, [this, request, trace] { emit samplesAnswered(request, trace); },
                                          Qt::QueuedConnection);
            },
            Qt::QueuedConnection);
    return request;
}

void SqlHistoryStore::onFailed(const QString &message)
{
    const bool was = m_recording;
    m_recording = false;
    m_pending.clear();
    if (was)
        emit recordingStopped(message);
}

void SqlHistoryStore::onResumed(const QString &message)
{
    m_recording = true;
    emit recordingResumed(message);
}

} // namespace jumo
