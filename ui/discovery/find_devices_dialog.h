#pragma once
// Device > Find devices… (issue 56): one sweep of every serial port and CAN bus
// (discovery::BenchSweep), with its progress and Cancel, the devices found in a table (link,
// port, rate, family, model, serial number, address or node, firmware) with a Connect button
// each and Connect all, the conflicts in red with their evidence and what to do, and why each
// port or bus where nothing answered showed nothing. The extra ports and buses, Modbus on or
// off and the time limit are remembered. "Simulated bench" starts simulated devices to find.
#include "core/discovery/bench_sweep.h"
#include "links/link_opener.h"

#include <QDialog>

#include <functional>
#include <memory>

QT_BEGIN_NAMESPACE
class QCheckBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;
QT_END_NAMESPACE

namespace imudesk::discovery {
class SimulatedBench;
}

namespace imudesk::ui {

class FindDevicesDialog : public QDialog {
    Q_OBJECT
public:
    // connect: opens a link in a tab of its own; false with why.
    using ConnectFn = std::function<bool(device::LinkRequest, QString *error)>;
    explicit FindDevicesDialog(ConnectFn connect, QWidget *parent = nullptr);
    ~FindDevicesDialog() override;

    enum Column { ColLink, ColPort, ColRate, ColFamily, ColModel, ColSerial, ColAddress, ColFirmware, ColConnect, ColCount };

    // Starts a sweep of the ports and buses the fields and the machine hold.
    void start();
    void cancel();
    // Starts the simulated bench and adds its ports and bus to the sweep (false: why in the status).
    // canInterface: its virtualcan interface (a test's own server: "tcp://127.0.0.1:PORT/can0").
    bool useSimulatedBench(bool on, const QString &canInterface = QStringLiteral("can1"));
    void setTimeLimit(int seconds);
    discovery::SweepOptions options() const;
    bool isRunning() const { return m_sweep.running(); }
    const discovery::SweepResult &result() const { return m_sweep.result(); }

    QTableWidget *table() const { return m_table; }
    QListWidget *findings() const { return m_findings; }
    QProgressBar *progressBar() const { return m_progress; }
    QPushButton *startButton() const { return m_start; }
    QPushButton *cancelButton() const { return m_cancel; }
    QPushButton *connectAllButton() const { return m_connectAll; }
    QLineEdit *portsEdit() const { return m_ports; }
    QLineEdit *busesEdit() const { return m_buses; }
    QCheckBox *onlyListedBox() const { return m_onlyListed; }
    QString statusText() const;
    // Connects the device of a row (its own tab); false with the reason shown.
    bool connectRow(int row);

    // Cancels a sweep under way and remembers the fields.
    void done(int result) override;

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void addDevice(const discovery::FoundDevice &d);
    void showFindings();
    void onProgress(int done, int total, const QString &port, const QString &detail);
    void onFinished();
    void setRunning(bool on);
    void loadSettings();
    void saveSettings() const;
    // The ports and buses in the fields, the simulated bench's left out.
    void listedWithoutBench(QStringList *ports, QStringList *buses) const;

    ConnectFn m_connect;
    discovery::BenchSweep m_sweep;
    QList<discovery::FoundDevice> m_found;
    std::shared_ptr<discovery::SimulatedBench> m_bench;
    QLabel *m_intro = nullptr;
    QLabel *m_portsLabel = nullptr;
    QLineEdit *m_ports = nullptr;
    QLabel *m_busesLabel = nullptr;
    QLineEdit *m_buses = nullptr;
    QCheckBox *m_modbus = nullptr;
    QCheckBox *m_onlyListed = nullptr;
    QCheckBox *m_simulated = nullptr;
    QLabel *m_timeLabel = nullptr;
    QSpinBox *m_time = nullptr;
    QPushButton *m_start = nullptr;
    QPushButton *m_cancel = nullptr;
    QPushButton *m_connectAll = nullptr;
    QPushButton *m_close = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_status = nullptr;
    QTableWidget *m_table = nullptr;
    QLabel *m_findingsLabel = nullptr;
    QListWidget *m_findings = nullptr;
};

} // namespace imudesk::ui
