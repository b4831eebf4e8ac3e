// Where a trend gets recorded values from: a station's own store, or (for a remote
// viewer) the station over MQTT. Answers come later, by signal, so no view ever waits
// on a disk, a database server or a network.
#pragma once

#include "history/historytypes.h"

#include <QObject>

namespace jumo {

class HistorySource : public QObject
{
    Q_OBJECT

public:
    using QObject::QObject;

    // The steps and gaps of one entry over [fromMs, toMs) (see HistoryTrace): answered by
    // samplesAnswered with the number returned here, also when it fails (trace.error).
    virtual quint64 requestSamples(const HistoryQuery &query) = 0;

signals:
    void samplesAnswered(quint64 request, const jumo::HistoryTrace &trace);
};

} // namespace jumo
