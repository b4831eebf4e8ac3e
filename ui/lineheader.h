// The header of a line's group on the overview: its name, its address and its state in
// words ("Connected", "Line lost: ...", "Disconnected"), with a mark and a band colour
// that say the same (never the colour alone). Clicking it makes the line the current one.
#pragma once

#include "bus/devicesource.h"

#include <QFrame>

class QLabel;

namespace jumo {

class ElidedLabel;
class StationLine;

class LineHeader : public QFrame
{
    Q_OBJECT

public:
    explicit LineHeader(StationLine *line, QWidget *parent = nullptr);
    // A header its owner feeds through display() (a remote line's).
    explicit LineHeader(const QString &name, QWidget *parent = nullptr);

    // Null for a header fed by its owner.
    StationLine *line() const { return m_line; }
    void display(const QString &address, int devices, LineState state, const QString &stateText);
    // The state text as shown ("Line lost: ..."), for tests.
    QString stateText() const;
    // Reads the line's name, address, devices and state again; also after a theme change.
    void refresh();

signals:
    void activated(jumo::StationLine *line);

protected:
    void mouseReleaseEvent(QMouseEvent *event) override;

private:
    void build();

    StationLine *m_line = nullptr;
    QString m_lineName;
    QLabel *m_name;
    ElidedLabel *m_address;
    ElidedLabel *m_state;
};

} // namespace jumo
