// A one-line label that shows as much of its text as fits, ending in "…", and has the
// whole text as its tooltip while it is cut: for status lines of any length.
#pragma once

#include <QLabel>

namespace jumo {

class ElidedLabel : public QLabel
{
    Q_OBJECT

public:
    explicit ElidedLabel(QWidget *parent = nullptr);

    // Replaces QLabel::setText for this label: the text shown is elided from it.
    void setFullText(const QString &text);
    QString fullText() const { return m_full; }

    QSize minimumSizeHint() const override;
    QSize sizeHint() const override;

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    void elide();

    QString m_full;
};

} // namespace jumo
