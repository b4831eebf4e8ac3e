#include "parametervaluedelegate.h"

#include "models/parametereditmodel.h"
#include "bus/valuetext.h"
#include "protocol/valueformat.h"
#include "theme.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QLineEdit>

namespace jumo {

namespace {

// "0.0 to 100.0 %", "0 to 65535 s": what the field takes, as a hint inside it.
QString rangeHint(const RegisterEntry &e)
{
    std::optional<double> lo = e.minimum;
    std::optional<double> hi = e.maximum;
    switch (e.type) {
    case ValueType::Int16:
        lo = std::max(lo.value_or(-32768), -32768.0);
        hi = std::min(hi.value_or(32767), 32767.0);
        break;
    case ValueType::UInt16:
        lo = std::max(lo.value_or(0), 0.0);
        hi = std::min(hi.value_or(65535), 65535.0);
        break;
    default:
        break;
    }
    QString range;
    if (lo && hi)
        range = ParameterValueDelegate::tr("%1 to %2").arg(ValueFormat::limit(*lo, e), ValueFormat::limit(*hi, e));
    else if (lo)
        range = ParameterValueDelegate::tr("%1 or more").arg(ValueFormat::limit(*lo, e));
    else if (hi)
        range = ParameterValueDelegate::tr("up to %1").arg(ValueFormat::limit(*hi, e));
    return ValueFormat::joinUnit(range, e.unit).trimmed();
}

} // namespace

ParameterValueDelegate::ParameterValueDelegate(ParameterEditModel *model, QObject *parent)
    : QStyledItemDelegate(parent), m_model(model)
{
}

QWidget *ParameterValueDelegate::createEditor(QWidget *parent, const QStyleOptionViewItem &option,
                                              const QModelIndex &index) const
{
    const RegisterEntry *e = m_model->entry(index.data(ParameterEditModel::EntryIdRole).toString());
    if (!e || index.column() != ParameterEditModel::NewValueColumn)
        return nullptr;
    if (e->type == ValueType::Enum || e->type == ValueType::Bool) {
        auto *choice = new QComboBox(parent);
        choice->setObjectName(QStringLiteral("parameterChoice"));
        if (e->type == ValueType::Bool) {
            choice->addItem(tr("Off"), QStringLiteral("0"));
            choice->addItem(tr("On"), QStringLiteral("1"));
        } else {
            for (auto it = e->enumValues.cbegin(); it != e->enumValues.cend(); ++it)
                choice->addItem(QCoreApplication::translate("jumo::maps", it.value().toUtf8().constData()),
                                QString::number(it.key()));
        }
        return choice;
    }
    auto *edit = qobject_cast<QLineEdit *>(QStyledItemDelegate::createEditor(parent, option, index));
    if (!edit)
        edit = new QLineEdit(parent);
    edit->setObjectName(QStringLiteral("parameterInput"));
    edit->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    const QString hint = rangeHint(*e);
    edit->setPlaceholderText(hint);
    QStringList tip;
    if (!hint.isEmpty())
        tip << tr("Takes %1").arg(hint);
    if (e->type == ValueType::Float && e->precision.kind == DisplayPrecision::Kind::Decimals)
        tip << tr("The device shows %n decimal(s)", nullptr, e->precision.digits);
    tip << tr("Enter takes the value, Escape leaves it as it was; an empty field drops the change.");
    edit->setToolTip(tip.join(QLatin1Char('\n')));
    return edit;
}

void ParameterValueDelegate::setEditorData(QWidget *editor, const QModelIndex &index) const
{
    const QString text = index.data(Qt::EditRole).toString();
    // What the field started with: taking it back unchanged is no change (the device's
    // 12.34 shown as 12.3 never becomes a write of 12.3).
    editor->setProperty("jumoInitial", text);
    if (auto *choice = qobject_cast<QComboBox *>(editor)) {
        choice->setCurrentIndex(std::max(0, choice->findData(text)));
        editor->setProperty("jumoInitial", choice->currentData().toString());
        editor->setProperty("jumoHadValue", !text.isEmpty());
    } else if (auto *edit = qobject_cast<QLineEdit *>(editor)) {
        edit->setText(text);
        edit->selectAll();
    }
}

void ParameterValueDelegate::setModelData(QWidget *editor, QAbstractItemModel *, const QModelIndex &index) const
{
    const QString id = index.data(ParameterEditModel::EntryIdRole).toString();
    QString value;
    if (auto *choice = qobject_cast<QComboBox *>(editor))
        value = choice->currentData().toString();
    else if (auto *edit = qobject_cast<QLineEdit *>(editor))
        value = edit->text();
    const bool hadValue = editor->property("jumoHadValue").isValid() ? editor->property("jumoHadValue").toBool() : true;
    if (value == editor->property("jumoInitial").toString() && hadValue)
        return;
    QString message;
    if (!m_model->setNewValue(id, value, &message))
        emit inputRefused(id, message);
    else if (!message.isEmpty())
        emit inputNote(id, message);
    else
        emit inputTaken(id);
}

void ParameterValueDelegate::initStyleOption(QStyleOptionViewItem *option, const QModelIndex &index) const
{
    QStyledItemDelegate::initStyleOption(option, index);
    if (!index.parent().isValid())
        return;
    auto colour = [option](Theme::Role role) { option->palette.setColor(QPalette::Text, Theme::color(role)); };
    switch (index.column()) {
    case ParameterEditModel::NameColumn:
    case ParameterEditModel::NewValueColumn:
        // Bold and a mark: a change is never told by colour alone.
        if (index.data(ParameterEditModel::ChangedRole).toBool())
            option->font.setBold(true);
        break;
    case ParameterEditModel::DeviceColumn: {
        const auto validity = Validity(index.data(ParameterEditModel::ValidityRole).toInt());
        if (validity != Validity::Current)
            colour(Theme::Role::Hint);
        else if (index.data(ParameterEditModel::ErrorValueRole).toBool())
            colour(Theme::Role::ErrorValue);
        if (validity == Validity::Stale)
            option->font.setItalic(true);
        break;
    }
    case ParameterEditModel::ResultColumn:
        switch (WriteCommand::State(index.data(ParameterEditModel::WriteStateRole).toInt())) {
        case WriteCommand::State::Idle:
            colour(Theme::Role::Hint);
            break;
        case WriteCommand::State::Pending:
            colour(Theme::Role::Pending);
            break;
        case WriteCommand::State::Confirmed:
            colour(Theme::Role::Confirmed);
            break;
        case WriteCommand::State::Refused:
            colour(Theme::Role::Refused);
            break;
        case WriteCommand::State::Unknown:
            colour(Theme::Role::Unknown);
            option->font.setBold(true);
            break;
        }
        break;
    default:
        break;
    }
    option->fontMetrics = QFontMetrics(option->font);
}

} // namespace jumo
