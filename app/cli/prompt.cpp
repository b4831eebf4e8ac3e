#include "prompt.h"

#include <QSocketNotifier>

#include <cerrno>
#include <unistd.h>

namespace jumo {

Prompt::Prompt(QTextStream &out, int inputFd, QObject *parent) : QObject(parent), m_out(out), m_fd(inputFd)
{
}

Prompt::~Prompt() = default;

void Prompt::ask(const QString &question, const std::function<void(const QString &)> &answered)
{
    m_out << question << Qt::flush;
    m_answered = answered;
    m_line.clear();
    m_notifier = new QSocketNotifier(m_fd, QSocketNotifier::Read, this);
    connect(m_notifier, &QSocketNotifier::activated, this, &Prompt::readInput);
}

void Prompt::readInput()
{
    // One byte at a time: what follows the line stays for whoever reads stdin next.
    char byte = 0;
    const ssize_t n = ::read(m_fd, &byte, 1);
    if (n < 0 && (errno == EINTR || errno == EAGAIN))
        return;
    if (n == 1 && byte != '\n') {
        m_line += byte;
        return;
    }
    answer();   // a line end, the end of input, or an error
}

void Prompt::answer()
{
    m_notifier->setEnabled(false);
    m_notifier->deleteLater();
    m_notifier = nullptr;
    const auto answered = std::move(m_answered);
    answered(QString::fromLocal8Bit(m_line).trimmed());
}

} // namespace jumo
