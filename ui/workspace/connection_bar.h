#pragma once
// The strip at the top of the main window: port, baud rate, Connect/Disconnect and
// Refresh. Lists serial ports (rescanned every 2 s while visible) and the simulated
// devices. It only reports what the user chose; the main window opens the session.
#include "device/session_types.h"
#include "workspace/port_choice.h"

#include <QTimer>
#include <QWidget>

#include <functional>
#include <vector>

class QComboBox;
class QLabel;
class QPushButton;
class QToolButton;

namespace imudesk::ui {

class ConnectionBar : public QWidget {
    Q_OBJECT
public:
    static constexpr int kPortScanIntervalMs = 2000;

    explicit ConnectionBar(QWidget *parent = nullptr);

    PortChoice selectedPort() const;
    // Selects `choice`, adding it to the list when it is not there (e.g. a path given on the command line).
    void selectPort(const PortChoice &choice);
    // The simulated devices listed below the serial ports (the family plug-ins'), asked for
    // whenever the list is rebuilt.
    void setSimulatedDevices(std::function<std::vector<SimulatedDevice>()> devices);
    int selectedBaud() const; // 0 = auto-detect
    void selectBaud(int baud);
    // Enables the choosers and flips the button between Connect and Disconnect.
    void setSessionState(device::SessionState state);
    // What the current tab is connected to ("Simulated HI14 (Modbus)", "/dev/ttyUSB0"): shown
    // in place of the port list while connected, so the bar never names another device.
    void setConnectedTarget(const QString &target);
    QString shownTarget() const; // the connected target on show, or the selected port's text
    // Texts of every entry in the port list (for tests and diagnostics).
    QStringList portTexts() const;

public Q_SLOTS:
    // True while the port list is rescanned every kPortScanIntervalMs: shown and not connected.
    bool isScanningPorts() const { return m_scanTimer.isActive(); }
    void refreshPorts();

Q_SIGNALS:
    void connectRequested();
    // "Find devices…": one sweep of every port and bus (Device > Find devices…).
    void findDevicesRequested();
    void disconnectRequested();

protected:
    void changeEvent(QEvent *event) override;
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;

private:
    void retranslateUi();
    void rebuildPortCombo();
    void onButtonClicked();
    void updateScanning();
    void updateTargetLabel();
    QString portText(const PortChoice &choice) const;

    struct PortEntry {
        PortChoice choice;
        QString description; // serial: description and serial number
        QString toolTip;
        bool operator==(const PortEntry &) const = default;
    };

    QLabel *m_portLabel = nullptr;
    QComboBox *m_portCombo = nullptr;
    QLabel *m_targetLabel = nullptr;
    QString m_target;
    QToolButton *m_refreshButton = nullptr;
    QToolButton *m_findButton = nullptr;
    QLabel *m_baudLabel = nullptr;
    QComboBox *m_baudCombo = nullptr;
    QPushButton *m_connectButton = nullptr;
    QTimer m_scanTimer;
    std::vector<PortEntry> m_serialPorts;
    std::vector<PortChoice> m_extraPorts; // chosen programmatically, not found by the scan
    std::function<std::vector<SimulatedDevice>()> m_simulatedDevices;
    std::vector<SimulatedDevice> m_simulated;
    device::SessionState m_state = device::SessionState::Closed;
};

} // namespace imudesk::ui
