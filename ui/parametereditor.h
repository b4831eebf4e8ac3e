// The Parameters tab of a device page: the device's parameters in a tree by the manual's
// groups, changes prepared in place (typed, or filled from a backup file), searched, and
// written together after one preview, each verified by reading it back.
#pragma once

#include "bus/bus.h"
#include "parameterwritepreview.h"
#include "theme.h"

#include <QPointer>
#include <QWidget>

class QLabel;
class QLineEdit;
class QPushButton;
class QSortFilterProxyModel;
class QTreeView;

namespace jumo {

class ParameterEditModel;
class ViewInterest;
class ParameterTransfer;
class ParameterValueDelegate;

class ParameterEditor : public QWidget
{
    Q_OBJECT

public:
    ParameterEditor(Bus *bus, DeviceId device, QWidget *parent = nullptr);
    ~ParameterEditor() override;

    // Nothing is edited, filled in or written; the values are still shown.
    void setReadOnly(bool readOnly);
    // How the write preview names the device (see DeviceTitle).
    void setDeviceTitle(const QString &title) { m_deviceTitle = title; }
    bool isEmpty() const;
    void focusSearch();

    // Fills the new values with those of a backup file that differ from the device
    // (read afresh first); what came of it is in status().
    void loadBackup(const QString &path);
    // Shows the preview of the changes; accepting it writes them.
    void requestWrite();
    void discardChanges();
    bool isBusy() const;
    QString status() const;

    ParameterEditModel *model() const { return m_model; }
    QTreeView *tree() const { return m_tree; }
    QLineEdit *searchField() const { return m_search; }
    // The preview while it is open, else null.
    ParameterWritePreview *preview() const { return m_preview; }

signals:
    // A write of changes has ended (every change confirmed, refused, unknown or not sent).
    void writeEnded();
    // A backup has been compared and its differences filled in, or refused.
    void backupLoaded();

protected:
    // While visible, the parameters are read as live values, not once a minute.
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;

private:
    void writeChanges(ParameterWritePreview *preview);
    void onEntryWritten(const QString &id, const WriteOutcome &outcome);
    void onWriteFinished(int succeeded, int failed, bool cancelled);
    void onConditionChanged(DeviceId device);
    void updateActions();
    void showStatus(const QString &text, Theme::Role role = Theme::Role::Hint);
    void applyFilter(const QString &text);
    bool deviceAnswers() const;
    QString notAnsweringText() const;

    Bus *m_bus;
    DeviceId m_device;
    ParameterEditModel *m_model;
    ViewInterest *m_interest;
    QSortFilterProxyModel *m_filter;
    ParameterValueDelegate *m_delegate;
    ParameterTransfer *m_transfer;
    QTreeView *m_tree;
    QLineEdit *m_search;
    QLabel *m_noMatch;
    QLabel *m_eepromNote;
    QLabel *m_pendingLabel;
    QLabel *m_status;
    QPushButton *m_load;
    QPushButton *m_discard;
    QPushButton *m_write;
    QPushButton *m_stop;
    QPointer<ParameterWritePreview> m_preview;
    QStringList m_written;     // the changes of the write under way
    QStringList m_writing;     // of those, the ones not reported yet
    QString m_deviceTitle;
    QString m_stopReason;      // why the rest were not written, when the job was stopped
    bool m_readOnly = false;
};

} // namespace jumo
