#pragma once
// Configuration over CAN for one CanSession: output period per J1939 PGN / CANopen TPDO (or
// the HEC495 PDO rate), SYNC mode, "Send SYNC" and periodic SYNC, heartbeat, node ID (the
// session follows it), CAN bit rate, attitude reset, output on/off, save / reset / factory,
// and the node scan with progress and cancel. Every write is confirmed by the device's reply
// or read back by the session; the outcome goes to the panel's log.
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
QT_END_NAMESPACE

namespace imudesk::ui {

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

Q_SIGNALS:
    // A request finished (also written to the log).
    void requestDone(bool ok, const QString &message);

private:
    void refreshForProtocol();
    void track(quint64 id, const QString &what);
    void onResult(const device::CanRequestResult &r);
    void applyPeriod();

    QPointer<device::CanSession> m_session;
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
