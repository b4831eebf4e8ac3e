// A table of one family's register map for views: address, id, label, type, access,
// storage, unit, group; one row per register.
#pragma once

#include "protocol/registermap.h"

#include <QAbstractTableModel>

#include <memory>

namespace jumo {

class RegisterMapModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column { AddressColumn, IdColumn, LabelColumn, TypeColumn, AccessColumn, StorageColumn, UnitColumn,
                  GroupColumn, ColumnCount };

    explicit RegisterMapModel(QObject *parent = nullptr);

    void setMap(std::shared_ptr<const RegisterMap> map);
    std::shared_ptr<const RegisterMap> map() const { return m_map; }

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    std::shared_ptr<const RegisterMap> m_map;
};

} // namespace jumo
