// A question on the terminal that does not stop the event loop while it waits: the
// answer is read from stdin as it comes, so Ctrl-C (or SIGTERM) ends the command at
// once instead of after the next line.
#pragma once

#include <QByteArray>
#include <QObject>
#include <QTextStream>

#include <functional>

class QSocketNotifier;

namespace jumo {

class Prompt : public QObject
{
    Q_OBJECT

public:
    Prompt(QTextStream &out, int inputFd = 0, QObject *parent = nullptr);
    ~Prompt() override;

    // Prints the question and calls answered() with the line typed (without the line
    // end; what there was at the end of input). Stops listening after it.
    void ask(const QString &question, const std::function<void(const QString &answer)> &answered);
    bool isWaiting() const { return m_notifier != nullptr; }

private:
    void readInput();
    void answer();

    QTextStream &m_out;
    int m_fd;
    QSocketNotifier *m_notifier = nullptr;
    QByteArray m_line;
    std::function<void(const QString &)> m_answered;
};

} // namespace jumo
