// The parameters of one device as a tree by the manual's groups, for an editor: the
// device's value with its validity, a new value prepared but not yet written, and what
// became of the last write of each. Writing is the caller's: it takes changedIds() and
// newValue(), and reports each outcome back with setOutcome().
#pragma once

#include "bus/bus.h"
#include "models/writecommand.h"

#include <QAbstractItemModel>

#include <memory>

namespace jumo {

class ParameterEditModel : public QAbstractItemModel
{
    Q_OBJECT

public:
    enum Column { NameColumn, DeviceColumn, NewValueColumn, UnitColumn, StorageColumn, ResultColumn, ColumnCount };
    // Fonts and colours are the view's business: it reads these roles.
    enum Role {
        EntryIdRole = Qt::UserRole + 1,   // empty on a group row
        ValidityRole,                     // int(Validity) of the device's value
        ChangedRole,                      // bool: a new value waits to be written
        WriteStateRole,                   // int(WriteCommand::State) of the last write
        SearchTextRole,                   // what a search looks through: label, id, address
        ErrorValueRole,                   // bool: the device reports an error value
    };

    ParameterEditModel(Bus *bus, DeviceId device, QObject *parent = nullptr);

    // The entries an editor lists: the map's writable parameters, reserved ones left out.
    static bool isListed(const RegisterEntry &entry);

    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &child) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    const RegisterMap &map() const { return *m_map; }
    const RegisterEntry *entry(const QString &id) const;
    QModelIndex indexOf(const QString &id, int column = NameColumn) const;
    // Every listed entry, in the tree's order.
    QStringList entryIds() const;
    int eepromCount() const;

    // A new value as a person types it: numbers in the locale's way or with a dot, an
    // enum's value or label. Refused (false, why in message) when it is no value of the
    // entry or out of its range; a value the device already holds is no change, and any
    // change waiting is dropped (true, a note in message). Empty text drops the change.
    bool setNewValue(const QString &id, const QString &typed, QString *message = nullptr);
    // A new value as the codec takes it (a parameter file's text), with the same checks.
    bool setExactValue(const QString &id, const QString &exact, QString *message = nullptr);
    // Drops the change of one entry, or of all, with what their last writes said.
    void revert(const QString &id);
    void discardAll();

    QStringList changedIds() const;
    int changeCount() const { return int(m_changes.size()); }
    bool isChanged(const QString &id) const { return m_changes.contains(id); }
    // The change's value as the codec takes it; empty when there is none.
    QString newValue(const QString &id) const { return m_changes.value(id); }
    // As a person reads them: the change, and the device's value ("—" when unknown).
    QString newValueText(const QString &id) const;
    QString deviceValueText(const QString &id) const;
    // The device's value as an edit starts from: every digit the device holds.
    QString editText(const QString &id) const;

    // Read-only mode, or a write under way: nothing can be edited.
    void setReadOnly(bool readOnly);
    bool isReadOnly() const { return m_readOnly; }
    void setLocked(bool locked);
    bool isLocked() const { return m_locked; }

    // What became of writes: under way, then each one's outcome. A confirmed change
    // leaves the changes; any other stays, with its outcome shown.
    void setWriting(const QStringList &ids);
    void setOutcome(const QString &id, const WriteOutcome &outcome);
    // Not written at all (stopped before its turn): the change stays, and says so.
    void setNotWritten(const QString &id, const QString &reason);
    WriteCommand::State writeState(const QString &id) const { return m_results.value(id).state; }
    QString writeMessage(const QString &id) const { return m_results.value(id).message; }
    QString resultText(const QString &id) const;

signals:
    void changeCountChanged(int count);

private:
    struct Group
    {
        QString title;
        QList<const RegisterEntry *> entries;
    };
    struct Result
    {
        WriteCommand::State state = WriteCommand::State::Idle;
        QString message;
        QString readBack;   // the value read back that confirmed the write, as shown
        // The read-back itself, and when it came (the bus's clock): the device value
        // until a poll reads one newer.
        DecodedValue readBackValue;
        qint64 readBackMs = -1;
    };
    // The confirmed read-back of the entry when it is newer than what the polls have.
    const DecodedValue *newerReadBack(const QString &id, const EntryState *state) const;

    void onEntriesUpdated(DeviceId device, const QStringList &ids);
    // The entry of a parameter that may be edited now; else null, with the reason.
    const RegisterEntry *editableEntry(const QString &id, QString *message) const;
    bool takeValue(const RegisterEntry &e, const QString &exact, QString *message);
    // Why a number is no value of the entry, or empty: range, whole numbers.
    QString rangeProblem(const RegisterEntry &e, double value, const QString &typed) const;
    QString displayOf(const RegisterEntry &e, const QString &exact) const;
    void emitRow(const QString &id);
    void emitGroupTitle(const QString &id);
    void setChanged(const QString &id, const QString &exact);

    Bus *m_bus;
    DeviceId m_device;
    std::shared_ptr<const RegisterMap> m_map;
    QList<Group> m_groups;
    QHash<QString, QPair<int, int>> m_position;   // id -> group, row
    QHash<QString, QString> m_changes;            // id -> new value, exact
    QHash<QString, Result> m_results;
    bool m_readOnly = false;
    bool m_locked = false;
};

} // namespace jumo
