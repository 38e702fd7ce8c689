#pragma once
// Register browser dock for a Modbus session: the device's register map as a table with live
// raw and scaled values (read on a clock while the dock is visible), editable where writable
// (the session writes and reads back; the outcome shows below the table), and a raw request
// line (function 03 or 06, address, count or value) for registers outside the map.
#include "itemmodels/register_table_model.h"

#include <QDockWidget>
#include <QPointer>
#include <QSet>
#include <QTimer>

QT_BEGIN_NAMESPACE
class QComboBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;
class QSpinBox;
class QTableView;
QT_END_NAMESPACE

namespace imudesk::device {
class ModbusSession;
struct ModbusRegisterReply;
} // namespace imudesk::device

namespace imudesk::ui {

class RegisterBrowser : public QDockWidget {
    Q_OBJECT
public:
    static constexpr int kDefaultRefreshMs = 500;

    explicit RegisterBrowser(device::ModbusSession *session, QWidget *parent = nullptr);

    // The map shown; follows the session's identity (edition, HEC495) by itself.
    void setMap(const protocol::modbus::RegisterMap &map);
    void setRefreshInterval(int ms);

    models::RegisterTableModel *model() { return &m_model; }
    QTableView *view() const { return m_view; }
    QString statusText() const;
    QString rawResultText() const;

public Q_SLOTS:
    // Reads every register of the map once.
    void refresh();
    // function 3: read `countOrValue` registers; function 6: write `countOrValue` (no read-back).
    void sendRawRequest(int function, int address, int countOrValue);

private:
    void onRegistersRead(const device::ModbusRegisterReply &reply);
    void onWriteFinished(const device::ModbusRegisterReply &reply);
    void onIdentity(const model::DeviceIdentity &identity);
    void showStatus(const QString &text, bool error);
    void onSendClicked();
    void updateRawInputs();

    QPointer<device::ModbusSession> m_session;
    models::RegisterTableModel m_model;
    QTableView *m_view = nullptr;
    QLabel *m_status = nullptr;
    QComboBox *m_function = nullptr;
    QSpinBox *m_address = nullptr;
    QSpinBox *m_countOrValue = nullptr;
    QPushButton *m_send = nullptr;
    QPlainTextEdit *m_rawResult = nullptr;
    QTimer m_refresh;
    QSet<quint64> m_tableReads;
    QSet<quint64> m_rawIds;
    QSet<quint64> m_writeIds;
};

} // namespace imudesk::ui
