// Asks for a line to add or change: its name, its address (a serial port, or a gateway's
// tcp:// or rtu+tcp:// URL), baud rate and format. Refuses a name that is taken or not
// fit for topics and file names, and an empty address.
#pragma once

#include "bus/bussettings.h"

#include <QDialog>

class QComboBox;
class QLabel;
class QLineEdit;

namespace jumo {

class LineDialog : public QDialog
{
    Q_OBJECT

public:
    // takenNames: the other lines' names.
    LineDialog(const QString &name, const BusSettings &settings, const QStringList &takenNames,
               QWidget *parent = nullptr);

    QString name() const;
    // The settings given, the others as they were.
    BusSettings settings() const;

    // Why a name cannot be a line's name, empty when it can: 1..32 of A-Z a-z 0-9 _ . -
    static QString nameProblem(const QString &name, const QStringList &takenNames);

    void accept() override;

private:
    BusSettings m_settings;
    QStringList m_taken;
    QLineEdit *m_name;
    QComboBox *m_address;
    QComboBox *m_baud;
    QComboBox *m_format;
    QLabel *m_problem;
};

} // namespace jumo
