// The one question before parameter changes are written: every change listed with the
// device's value and the new one, how many of them wear EEPROM, and which had a write
// of unknown outcome before. Accepting it is the confirmation of all of them.
#pragma once

#include <QDialog>

class QTableWidget;

namespace jumo {

class ParameterWritePreview : public QDialog
{
    Q_OBJECT

public:
    struct Change
    {
        QString id;
        QString label;         // translated
        QString deviceValue;   // as the editor shows it
        QString newValue;
        QString unit;
        bool eeprom = false;
        QString lastWrite;     // what the last write of this entry said, if it was not confirmed
    };

    ParameterWritePreview(const QString &deviceName, const QList<Change> &changes, QWidget *parent = nullptr);

    QList<Change> changes() const { return m_changes; }
    QTableWidget *table() const { return m_table; }

private:
    QList<Change> m_changes;
    QTableWidget *m_table;
};

} // namespace jumo
