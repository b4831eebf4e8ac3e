// The alarm, warning and status bits of a device's bit fields, one row per bit, for an
// LED grid: label, kind, on/off, and a tooltip with register, bit and the manual's words.
#pragma once

#include "bus/devicesource.h"

#include <QAbstractListModel>

namespace jumo {

class AlarmBitsModel : public QAbstractListModel
{
    Q_OBJECT

public:
    // A bit is on, off, or unknown (its word could not be read: neither on nor off).
    enum class BitState { Off, On, Unknown };
    enum Role { KindRole = Qt::UserRole + 1,
                BitStateRole,     // int(BitState)
                ValidityRole,     // int(Validity) of the word the bit is in
                ReferenceRole, GroupTitleRole };

    AlarmBitsModel(const DeviceSource *devices, DeviceId device, QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;

    // Alarm bits on, among the words that are known (current or stale).
    int activeAlarms() const { return m_activeAlarms; }
    // False while any word with alarm bits is unknown: then nobody can say "no alarm".
    bool alarmsKnown() const { return m_alarmsKnown; }
    // True while a word of the grid is stale: the count is the last known one, not a live one.
    bool alarmsStale() const { return m_alarmsStale; }
    int rowOf(const QString &reference) const;   // "entry.bit"

signals:
    void activeAlarmsChanged(int count);
    void alarmsKnownChanged(bool known);

private:
    struct Row
    {
        const RegisterEntry *entry;
        const BitDefinition *bit;
    };

    void onEntriesUpdated(DeviceId device, const QStringList &ids);
    BitState bitState(const Row &row) const;
    void recount();

    const DeviceSource *m_devices;
    DeviceId m_device;
    std::shared_ptr<const RegisterMap> m_map;
    QList<Row> m_rows;
    int m_activeAlarms = 0;
    bool m_alarmsKnown = false;
    bool m_alarmsStale = false;
};

} // namespace jumo
