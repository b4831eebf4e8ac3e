#include "outputcheck.h"

#include <QFileDevice>
#include <QTextStream>

#include <poll.h>

namespace jumo::OutputCheck {

bool failed(QTextStream &stream)
{
    stream.flush();
    const auto *file = qobject_cast<const QFileDevice *>(stream.device());
    return stream.status() == QTextStream::WriteFailed || (file && file->error() != QFileDevice::NoError);
}

bool closed(const QTextStream &stream)
{
    // A pipe without a reader polls as an error, a closed socket as hung up; a file
    // never does. Asked before a step that would go on unseen, so that it is not taken.
    const auto *file = qobject_cast<const QFileDevice *>(stream.device());
    if (!file || file->handle() < 0)
        return false;
    pollfd descriptor{file->handle(), POLLOUT, 0};
    return ::poll(&descriptor, 1, 0) == 1 && (descriptor.revents & (POLLERR | POLLHUP)) != 0;
}

} // namespace jumo::OutputCheck
