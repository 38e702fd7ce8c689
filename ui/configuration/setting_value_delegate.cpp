#include "configuration/setting_value_delegate.h"

#include "itemmodels/settings_table_model.h"

#include <QAbstractItemView>
#include <QComboBox>
#include <QLineEdit>
#include <QStyle>

#include <algorithm>

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
    // Every item in full in the list, however narrow the cell ("1 H… s)" before).
    box->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    QAbstractItemView *list = box->view();
    list->setTextElideMode(Qt::ElideNone);
    list->setMinimumWidth(list->sizeHintForColumn(0) + 2 * list->frameWidth()
                          + list->style()->pixelMetric(QStyle::PM_ScrollBarExtent) + 8);
    // A choice from the list is the new value at once; typed text still waits for Enter.
    auto *self = const_cast<SettingValueDelegate *>(this);
    connect(box, &QComboBox::activated, self, [self, box] {
        Q_EMIT self->commitData(box);
        Q_EMIT self->closeEditor(box, QAbstractItemDelegate::NoHint);
    });
    return box;
}

void SettingValueDelegate::updateEditorGeometry(QWidget *editor, const QStyleOptionViewItem &option,
                                                const QModelIndex &index) const
{
    QStyledItemDelegate::updateEditorGeometry(editor, option, index);
    QRect r = editor->geometry();
    const int wanted = std::max(r.width(), editor->sizeHint().width());
    const QWidget *view = editor->parentWidget();
    const int room = view ? view->width() : wanted;
    r.setWidth(std::min(wanted, room));
    if (view && r.right() >= room) // wider than the cell: grow to the left, inside the view
        r.moveRight(room - 1);
    editor->setGeometry(r);
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
