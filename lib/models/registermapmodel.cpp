#include "models/registermapmodel.h"

#include <QCoreApplication>

namespace jumo {

RegisterMapModel::RegisterMapModel(QObject *parent) : QAbstractTableModel(parent) { }

void RegisterMapModel::setMap(std::shared_ptr<const RegisterMap> map)
{
    beginResetModel();
    m_map = std::move(map);
    endResetModel();
}

int RegisterMapModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() || !m_map ? 0 : int(m_map->entries().size());
}

int RegisterMapModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant RegisterMapModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || !m_map || index.row() >= m_map->entries().size())
        return {};
    const RegisterEntry &e = m_map->entries().at(index.row());
    if (role == Qt::ToolTipRole) {
        QStringList parts;
        if (!e.notes.isEmpty())
            parts << e.notes;
        if (!e.erratum.isEmpty())
            parts << tr("Correction of the manual: %1").arg(e.erratum);
        return parts.join(QStringLiteral("\n\n"));
    }
    if (role != Qt::DisplayRole)
        return {};
    switch (index.column()) {
    case AddressColumn: return formatAddress(e.address);
    case IdColumn: return e.id;
    case LabelColumn: return QCoreApplication::translate("jumo::maps", e.label.toUtf8().constData());
    case TypeColumn: return valueTypeName(e.type);
    case AccessColumn: return accessName(e.access);
    case StorageColumn: return storageName(e.storage);
    case UnitColumn: return e.unit;
    case GroupColumn: return e.group;
    default: return {};
    }
}

QVariant RegisterMapModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case AddressColumn: return tr("Address");
    case IdColumn: return tr("Id");
    case LabelColumn: return tr("Label");
    case TypeColumn: return tr("Type");
    case AccessColumn: return tr("Access");
    case StorageColumn: return tr("Storage");
    case UnitColumn: return tr("Unit");
    case GroupColumn: return tr("Section");
    default: return {};
    }
}

} // namespace jumo
