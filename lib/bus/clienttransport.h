// The life cycle every transport of a real line shares, whatever carries its frames:
// closed, connecting, open; one request under way that ends exactly once (never from
// inside send()); its timeout; a loss said once (logged, lost()) with the request under
// way ended as LineDown; a close that does the same without a word. A subclass only
// opens and closes its link and frames requests and replies.
#pragma once

#include "bus/transport.h"

#include <QElapsedTimer>
#include <QTimer>

#include <optional>

namespace jumo {

class ClientTransport : public Transport
{
    Q_OBJECT

public:
    bool open(QString *error) final;
    void close() final;
    bool isOpen() const final { return m_state == State::Open; }
    bool isConnecting() const final { return m_state == State::Connecting; }
    void send(const ModbusRequest &request) final;

protected:
    enum class Link { Failed, Connecting, Open };

    explicit ClientTransport(QObject *parent = nullptr);

    // Who is at the far end, for messages and the log: "port /dev/ttyUSB0", "gateway 10.0.0.20:502".
    virtual QString peer() const = 0;
    // Opens the link: open at once, connecting (linkUp() or linkDown() follows), or
    // failed with the reason in *error.
    virtual Link openLink(QString *error) = 0;
    // Closes the link at once; nothing of the old link may reach this object afterwards.
    virtual void closeLink() = 0;
    // The request goes out now, over a link that stands; called once per request.
    virtual void transmit(const ModbusRequest &request) = 0;
    // The request's time (startReplyTimer) is up: the result it ends with.
    virtual ModbusResult timedOut(const ModbusRequest &request);

    // The link that was connecting stands now: opened(), and a waiting request goes out.
    void linkUp();
    // The link is gone: the line is lost (logged once, lost()), the request under way ends LineDown.
    void linkDown(const QString &reason);
    // The link is made anew (a stream that can no longer be framed), the line not given
    // up: requests wait for the new connection; if it fails, that is the loss.
    void relink(const QString &reason);

    // The request under way (sent or waiting to go out), or nullptr.
    const ModbusRequest *request() const { return m_request ? &*m_request : nullptr; }
    void startReplyTimer(int ms);
    // Ends the request under way with this result (a no-op when none is).
    void complete(const ModbusResult &result);
    // Ends it with a status and a reason.
    void fail(ModbusResult::Status status, const QString &reason);

    // A reply that was not taken: logged the first time and then at most once a minute
    // with how many followed, never once per reply (a lying peer would flood the log).
    void noteRejected(const QString &what);

private:
    enum class State { Closed, Connecting, Open };

    // Closed at once; a request under way ends as LineDown with the reason.
    void shutDown(const QString &reason);
    void onReplyTimeout();
    void deliver(const ModbusResult &result);
    // finished() from the event loop, unless the transport was opened again meanwhile.
    void emitLater(const ModbusResult &result);

    State m_state = State::Closed;
    std::optional<ModbusRequest> m_request;
    bool m_transmitted = false;
    bool m_inSend = false;   // finished() is queued while send() runs
    quint64 m_opened = 0;    // counts open(): a queued finished() of an earlier connection is dropped
    QTimer m_replyTimer;
    QElapsedTimer m_lastRejectLog;
    int m_rejectsUnlogged = 0;
};

} // namespace jumo
