// The alarm, warning and status bits of a device's bit fields, one row per bit, for an
// LED grid: label, kind, on/off, and a tooltip with register, bit and the manual's words.
#pragma once

#include "bus/bus.h"

#include <QAbstractListModel>

namespace jumo {

class AlarmBitsModel : public QAbstractListModel
{
    Q_OBJECT

public:
    enum Role { KindRole = Qt::UserRole + 1, ActiveRole, CurrentRole, ReferenceRole, GroupTitleRole };

    AlarmBitsModel(Bus *bus, DeviceId device, QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;

    int activeAlarms() const { return m_activeAlarms; }
    int rowOf(const QString &reference) const;   // "entry.bit"

signals:
    void activeAlarmsChanged(int count);

private:
    struct Row
    {
        const RegisterEntry *entry;
        const BitDefinition *bit;
    };

    void onEntriesUpdated(DeviceId device, const QStringList &ids);
    bool isActive(const Row &row) const;
    void recount();

    Bus *m_bus;
    DeviceId m_device;
    std::shared_ptr<const RegisterMap> m_map;
    QList<Row> m_rows;
    int m_activeAlarms = 0;
};

} // namespace jumo
