#pragma once
// Finds the Modbus devices on the bus: node IDs from..to (1-247) at the session's baud or at
// every baud of the module's table, with a progress bar and Cancel; each device that answers
// is listed with its identity. Double-clicking a row (or "Use") emits deviceChosen.
#include "device/modbus_types.h"

#include <QDialog>
#include <QPointer>

QT_BEGIN_NAMESPACE
class QCheckBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;
QT_END_NAMESPACE

namespace imudesk::device {
class ModbusSession;
}

namespace imudesk::ui {

class ModbusScanDialog : public QDialog {
    Q_OBJECT
public:
    explicit ModbusScanDialog(device::ModbusSession *session, QWidget *parent = nullptr);

    void setRange(int firstId, int lastId);
    void setAllBauds(bool on);
    bool isScanning() const { return m_scanning; }
    QProgressBar *progressBar() const { return m_progress; }
    QTableWidget *results() const { return m_table; }
    QPushButton *startButton() const { return m_start; }
    QPushButton *cancelButton() const { return m_cancel; }
    QString statusText() const;

public Q_SLOTS:
    void start();
    void cancel();

Q_SIGNALS:
    void deviceChosen(int nodeId, int baud);

private:
    void onFound(const device::ModbusScanHit &hit);
    void onFinished(const QList<device::ModbusScanHit> &hits, bool cancelled);
    void setScanning(bool on);

    QPointer<device::ModbusSession> m_session;
    QSpinBox *m_from = nullptr;
    QSpinBox *m_to = nullptr;
    QCheckBox *m_allBauds = nullptr;
    QPushButton *m_start = nullptr;
    QPushButton *m_cancel = nullptr;
    QPushButton *m_use = nullptr;
    QProgressBar *m_progress = nullptr;
    QTableWidget *m_table = nullptr;
    QLabel *m_status = nullptr;
    bool m_scanning = false;
};

} // namespace imudesk::ui
