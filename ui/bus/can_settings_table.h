#pragma once
// The settings a CAN device documents (protocol/can/can_setting_catalog.h), like the serial
// configuration table: per setting the value the module holds, read from it first (J1939
// register reads, CANopen SDO uploads), beside the new value to write, and after a write what
// the read-back found: "verified", "the module holds X" or why there was no answer. Settings the
// manual gives no read for (the HEC495's) say "not readable" and are confirmed by the module's
// write reply only. The module's values are read when the device's protocol is known, and on
// "Read from module".
#include "device/can_session.h"
#include "protocol/can/can_setting_catalog.h"

#include <QHash>
#include <QPointer>
#include <QWidget>

#include <optional>
#include <vector>

QT_BEGIN_NAMESPACE
class QPushButton;
class QTableWidget;
QT_END_NAMESPACE

namespace imudesk::ui {

class CanSettingsTable : public QWidget {
    Q_OBJECT
public:
    enum Column { SettingColumn, ModuleColumn, NewColumn, StatusColumn, ColumnCount };

    explicit CanSettingsTable(QWidget *parent = nullptr);

    // The table does not own the session; nullptr detaches it.
    void setSession(device::CanSession *session);
    // Reads every readable setting from the module.
    void readAll();
    // Writes the settings whose new value was changed, each read back.
    void writeChanged();
    bool busy() const { return !m_pending.isEmpty(); }

    // For tests and screen readers: a row's texts by the setting's name.
    QString moduleText(const QString &name) const;
    QString statusText(const QString &name) const;
    // Sets a row's new value as a person would (a choice's text or a number); false when the
    // row has no such value.
    bool setNewValue(const QString &name, const QString &text);
    QTableWidget *table() const { return m_table; }
    QPushButton *readButton() const { return m_read; }
    QPushButton *writeButton() const { return m_write; }

Q_SIGNALS:
    // Every request of a read or a write has ended.
    void idle();

protected:
    void changeEvent(QEvent *event) override;

private:
    struct Row {
        protocol::can::CanSetting setting;
        std::optional<uint32_t> module; // what the module holds, as last read or written
        bool edited = false;
        QWidget *editor = nullptr;      // QComboBox (choices) or QSpinBox
    };
    void rebuild();
    int rowOf(const QString &name) const;
    uint32_t editorValue(const Row &row) const;
    void setEditorValue(Row &row, uint32_t raw);
    void setStatus(int row, const QString &text, const QColor &colour, const QString &toolTip = {});
    void onResult(const device::CanRequestResult &r);
    void updateButtons();
    void retranslateUi();

    QPointer<device::CanSession> m_session;
    protocol::can::CanProtocol m_protocol = protocol::can::CanProtocol::Auto;
    std::vector<Row> m_rows;
    struct Pending {
        int row = -1;
        bool write = false;
        uint32_t raw = 0;
        bool retried = false;
    };
    QHash<quint64, Pending> m_pending;
    QList<QMetaObject::Connection> m_connections;
    QTableWidget *m_table;
    QPushButton *m_read;
    QPushButton *m_write;
};

} // namespace imudesk::ui
