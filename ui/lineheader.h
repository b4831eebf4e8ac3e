// The header of a line's group on the overview: its name, its address and its state in
// words ("Connected", "Line lost: ...", "Disconnected"), with a mark and a band colour
// that say the same (never the colour alone). Clicking it makes the line the current one.
#pragma once

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

    StationLine *line() const { return m_line; }
    // The state text as shown ("Line lost: ..."), for tests.
    QString stateText() const;
    // Reads the line's name, address, devices and state again; also after a theme change.
    void refresh();

signals:
    void activated(jumo::StationLine *line);

protected:
    void mouseReleaseEvent(QMouseEvent *event) override;

private:
    StationLine *m_line;
    QLabel *m_name;
    ElidedLabel *m_address;
    ElidedLabel *m_state;
};

} // namespace jumo
