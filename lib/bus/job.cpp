#include "bus/job.h"

#include <QMetaObject>

namespace jumo {

void Job::begin()
{
    m_running = true;
    m_cancelRequested = false;
    m_result = Result::None;
    m_errorText.clear();
}

void Job::cancel()
{
    if (!m_running || m_cancelRequested)
        return;
    m_cancelRequested = true;
    onCancel();
}

void Job::finish(Result result, const QString &errorText)
{
    if (!m_running)
        return;
    m_running = false;
    m_result = result;
    m_errorText = errorText;
    QMetaObject::invokeMethod(this, [this] { emit finished(this); }, Qt::QueuedConnection);
}

} // namespace jumo
