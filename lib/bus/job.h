// A long operation on a line (scan, backup, restore, report): started by its own start()
// with what it needs, cancelled, reporting progress, and ending with one finished signal,
// delivered queued, so nobody's reaction (a dialog, a next step) runs inside a bus
// callback. In the manner of KDE's KJob.
#pragma once

#include <QObject>
#include <QString>

namespace jumo {

class Job : public QObject
{
    Q_OBJECT

public:
    enum class Result { None, Succeeded, Failed, Cancelled };

    using QObject::QObject;

    bool isRunning() const { return m_running; }
    // Stops after the request under way; finished() follows with Cancelled.
    void cancel();
    bool isCancelled() const { return m_cancelRequested; }
    Result result() const { return m_result; }
    QString errorText() const { return m_errorText; }

signals:
    void progressChanged(int done, int total);
    // Exactly once per start, from the event loop.
    void finished(jumo::Job *job);

protected:
    // Called by start() of the subclass.
    void begin();
    // Ends the job; the signal follows from the event loop. Later calls are ignored.
    void finish(Result result, const QString &errorText = QString());
    // The subclass's part of cancel(): stop asking for more.
    virtual void onCancel() { }

private:
    bool m_running = false;
    bool m_cancelRequested = false;
    Result m_result = Result::None;
    QString m_errorText;
};

} // namespace jumo
