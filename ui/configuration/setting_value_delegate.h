#pragma once
// Editor for the "New value" column of SettingsTableModel: a combo box with the values
// the device can take (editable where free values are allowed, e.g. output periods), a
// line edit otherwise. A value the model refuses leaves the cell unchanged; the reason is
// reported through valueRefused(). A choice from the list counts as it is made (no Enter
// needed); the list shows every item in full.
#include <QStyledItemDelegate>

namespace imudesk::ui {

class SettingValueDelegate : public QStyledItemDelegate {
    Q_OBJECT
public:
    using QStyledItemDelegate::QStyledItemDelegate;

    QWidget *createEditor(QWidget *parent, const QStyleOptionViewItem &option, const QModelIndex &index) const override;
    void setEditorData(QWidget *editor, const QModelIndex &index) const override;
    void setModelData(QWidget *editor, QAbstractItemModel *model, const QModelIndex &index) const override;
    // As wide as the editor's text needs ("200 Hz (0.005 s)" in full), inside the view.
    void updateEditorGeometry(QWidget *editor, const QStyleOptionViewItem &option,
                              const QModelIndex &index) const override;

Q_SIGNALS:
    void valueRefused(const QString &reason) const;
};

} // namespace imudesk::ui
