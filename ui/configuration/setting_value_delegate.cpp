#include "configuration/setting_value_delegate.h"

#include "models/settings_table_model.h"

#include <QComboBox>
#include <QLineEdit>

namespace imudesk::ui {

using models::SettingsTableModel;

QWidget *SettingValueDelegate::createEditor(QWidget *parent, const QStyleOptionViewItem &option,
                                            const QModelIndex &index) const
{
    const QStringList values = index.data(SettingsTableModel::ChoicesRole).toStringList();
    if (values.isEmpty())
        return QStyledItemDelegate::createEditor(parent, option, index);
    auto *box = new QComboBox(parent);
    const QStringList labels = index.data(SettingsTableModel::ChoiceLabelsRole).toStringList();
    for (int i = 0; i < values.size(); ++i)
        box->addItem(i < labels.size() ? labels.at(i) : values.at(i), values.at(i));
    // Output periods take any whole number of milliseconds, not only the listed ones.
    const QString key = index.data(SettingsTableModel::KeyRole).toString();
    box->setEditable(key.startsWith(QLatin1String("LOG.")) && key != QLatin1String("LOG.HI83.MAP"));
    return box;
}

void SettingValueDelegate::setEditorData(QWidget *editor, const QModelIndex &index) const
{
    const QString current = index.data(Qt::EditRole).toString();
    if (auto *box = qobject_cast<QComboBox *>(editor)) {
        const int i = box->findData(current);
        if (i >= 0)
            box->setCurrentIndex(i);
        else if (box->isEditable())
            box->setEditText(current);
        return;
    }
    QStyledItemDelegate::setEditorData(editor, index);
}

void SettingValueDelegate::setModelData(QWidget *editor, QAbstractItemModel *model, const QModelIndex &index) const
{
    QString text;
    if (auto *box = qobject_cast<QComboBox *>(editor)) {
        const int i = box->findText(box->currentText());
        text = (i >= 0 && box->itemText(i) == box->currentText()) ? box->itemData(i).toString() : box->currentText();
    } else if (auto *line = qobject_cast<QLineEdit *>(editor)) {
        text = line->text();
    }
    if (!model->setData(index, text, Qt::EditRole)) {
        auto *m = qobject_cast<SettingsTableModel *>(model);
        Q_EMIT valueRefused(m ? m->lastError() : tr("the value was refused"));
    }
}

} // namespace imudesk::ui
