// Fuzz target: the alarm journal and write audit files (JSON lines) as read at start-up:
// torn lines, binary garbage, huge lines. Reading keeps what is readable and never fails.
#include "logs/eventlog.h"

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
    EventLog log(path);
    for (const QJsonObject &r : log.records())
        (void)r.value(QStringLiteral("time"));
    (void)log.exportCsv(dir.filePath(QStringLiteral("journal.csv")), {QStringLiteral("time"), QStringLiteral("device")});
    return 0;
}
