// The live values of one device on the bus, for a table view: section, label, value,
// unit, status and age of every readable entry. One dataChanged per poll block.
#pragma once

#include "bus/devicesource.h"
#include "models/viewinterest.h"

#include <QAbstractTableModel>
#include <QTimer>

namespace jumo {

class LiveValuesModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column { SectionColumn, LabelColumn, ValueColumn, UnitColumn, StatusColumn, AgeColumn, ColumnCount };
    // Colours are the view's business: it reads ValidityRole and ErrorValueRole.
    enum Role { EntryIdRole = Qt::UserRole + 1, StatusNameRole,
                ValidityRole,    // int(Validity): current, stale or unknown
                AgeMsRole, ErrorValueRole,
                NumericRole,     // double, only for a current good number
                ValueWithUnitRole };   // "91.9 V", as tiles and controls show it

    LiveValuesModel(const DeviceSource *devices, DeviceId device, QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    int rowOf(const QString &entryId) const { return m_rowOf.value(entryId, -1); }
    QString entryId(int row) const;
    // A view of these entries (empty: every row) is on screen, or not any more: the line
    // reads them sooner meanwhile.
    void setShown(const QObject *view, bool shown, const QStringList &entryIds = {});

private:
    void onEntriesUpdated(DeviceId device, const QStringList &ids);

    const DeviceSource *m_devices;
    DeviceId m_device;
    std::shared_ptr<const RegisterMap> m_map;
    QList<const RegisterEntry *> m_rows;
    QHash<QString, int> m_rowOf;
    QTimer m_ageTimer;
    ViewInterest m_interest;
};

} // namespace jumo
