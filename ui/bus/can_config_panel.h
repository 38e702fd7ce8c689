#pragma once
// Configuration over CAN for one CanSession: output period per J1939 PGN / CANopen TPDO (or
// the HEC495 PDO rate), a J1939 one-shot trigger of the chosen PGN, SYNC mode, "Send SYNC" and
// periodic SYNC, heartbeat, node ID (the session follows it), CAN bit rate, attitude reset,
// inclinometer axis directions, the HEC495's PDO and work modes, output on/off for the node or
// every node (NMT), save / reset / factory, and the node scan with progress and cancel. Every
// write is confirmed by the device's reply, read back, or (NMT) seen in the PDOs; the outcome
// goes to the panel's log. The rows a protocol does not have are disabled. A first page lists
// every setting of the device's catalogue with the value the module holds (CanSettingsTable).
#include "device/can_session.h"

#include <QPointer>
#include <QWidget>

QT_BEGIN_NAMESPACE
class QCheckBox;
class QComboBox;
class QLabel;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTabWidget;
QT_END_NAMESPACE

namespace imudesk::ui {

class CanSettingsTable;

class CanConfigPanel : public QWidget {
    Q_OBJECT
public:
    explicit CanConfigPanel(QWidget *parent = nullptr);

    // The panel does not own the session; nullptr detaches it.
    void setSession(device::CanSession *session);
    device::CanSession *session() const { return m_session; }

    // Widgets, for tests and for the integrator's layout.
    QComboBox *outputChoice() const { return m_output; }
    QSpinBox *periodSpin() const { return m_period; }
    QPushButton *applyPeriodButton() const { return m_applyPeriod; }
    QCheckBox *syncModeCheck() const { return m_syncMode; }
    QPushButton *sendSyncButton() const { return m_sendSync; }
    QSpinBox *syncPeriodSpin() const { return m_syncPeriod; }
    QSpinBox *heartbeatSpin() const { return m_heartbeat; }
    QSpinBox *nodeSpin() const { return m_node; }
    QPushButton *applyNodeButton() const { return m_applyNode; }
    QPushButton *scanButton() const { return m_scan; }
    QProgressBar *scanProgressBar() const { return m_scanProgress; }
    QPlainTextEdit *log() const { return m_log; }
    QPushButton *triggerButton() const { return m_trigger; }
    QCheckBox *inclXReversedCheck() const { return m_inclX; }
    QCheckBox *inclYReversedCheck() const { return m_inclY; }
    QPushButton *applyInclButton() const { return m_applyIncl; }
    QComboBox *pdoModeChoice() const { return m_pdoMode; }
    QComboBox *workModeChoice() const { return m_workMode; }
    QPushButton *applyModesButton() const { return m_applyModes; }
    QPushButton *allOnButton() const { return m_allOn; }
    QPushButton *allOffButton() const { return m_allOff; }
    // Every setting with the module's value (the first page).
    CanSettingsTable *settingsTable() const { return m_settings; }
    QTabWidget *tabs() const { return m_tabs; }

Q_SIGNALS:
    // A request finished (also written to the log).
    void requestDone(bool ok, const QString &message);

private:
    void refreshForProtocol();
    void track(quint64 id, const QString &what);
    void onResult(const device::CanRequestResult &r);
    void applyPeriod();

    QPointer<device::CanSession> m_session;
    CanSettingsTable *m_settings = nullptr;
    QTabWidget *m_tabs = nullptr;
    QLabel *m_protocol;
    QComboBox *m_output;
    QSpinBox *m_period;
    QPushButton *m_applyPeriod;
    QCheckBox *m_syncMode;
    QPushButton *m_sendSync;
    QSpinBox *m_syncPeriod;
    QSpinBox *m_heartbeat;
    QPushButton *m_applyHeartbeat;
    QSpinBox *m_node;
    QPushButton *m_applyNode;
    QComboBox *m_bitrate;
    QPushButton *m_applyBitrate;
    QComboBox *m_attitude;
    QPushButton *m_applyAttitude;
    QPushButton *m_outputOn;
    QPushButton *m_outputOff;
    QPushButton *m_trigger;
    QCheckBox *m_inclX;
    QCheckBox *m_inclY;
    QPushButton *m_applyIncl;
    QComboBox *m_pdoMode;
    QComboBox *m_workMode;
    QPushButton *m_applyModes;
    QPushButton *m_allOn;
    QPushButton *m_allOff;
    QPushButton *m_save;
    QPushButton *m_reset;
    QPushButton *m_factory;
    QPushButton *m_scan;
    QPushButton *m_cancelScan;
    QProgressBar *m_scanProgress;
    QPlainTextEdit *m_log;
    QList<QMetaObject::Connection> m_connections;
    QHash<quint64, QString> m_pending;
};

} // namespace imudesk::ui
