// Fuzz target: the alarm journal and write audit files (JSON lines) as the views and
// jumoctl read them: torn lines, binary garbage, huge lines, no newline at the end.
// Reading back and forth, filtering and exporting keep what is readable and never fail.
#include "logs/eventlogreader.h"
#include "logs/eventlogscanner.h"

#include <QFile>
#include <QTemporaryDir>

#include <cstdint>

using namespace jumo;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("journal.jsonl"));
    {
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate))
            return 0;
        f.write(reinterpret_cast<const char *>(data), qint64(size));
    }
    int backwards = 0;
    EventLogReader reader(path);
    while (const auto r = reader.previous()) {
        (void)r->value(QStringLiteral("time"));
        ++backwards;
    }
    // Lines found back to front (in small chunks) are the lines found front to back.
    QString error;
    const auto file = LogFile::open(path, &error);
    if (!file)
        abort();
    QList<qint64> forward;
    QList<qint64> backward;
    const qint64 end = file->linesFrom(0, file->size(), [&](const LogFile::Line &line) {
        forward << line.offset;
        return true;
    });
    for (qint64 cursor = file->lastLineEnd(file->size()); cursor > 0;) {
        cursor = file->linesBefore(cursor, 7, [&](const LogFile::Line &line) {
            backward.prepend(line.offset);
            return true;
        });
    }
    if (end != file->lastLineEnd(file->size()) || forward != backward)
        abort();
    const std::atomic_int query{1};
    EventLogScanner scanner(path, {QStringLiteral("time"), QStringLiteral("device")}, &query);
    int found = 0;
    QObject::connect(&scanner, &EventLogScanner::olderFound,
                     [&found](int, const QList<EventLogScanner::LineRef> &lines) { found += int(lines.size()); });
    scanner.start(1, QString(), 1 << 20);
    scanner.start(1, QStringLiteral("a"), 1 << 20);
    scanner.exportCsv(dir.filePath(QStringLiteral("journal.csv")));
    (void)backwards;
    return 0;
}
