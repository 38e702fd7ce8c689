#include "workspace/link_factory.h"

#include "bus/can_config_panel.h"
#include "bus/modbus_scan_dialog.h"
#include "calibration/hec495_calibration_wizard.h"
#include "ui/firmware/firmware_update_dialog.h"
#include "bus/can_monitor_widget.h"
#include "device/can_session.h"
#include "device/hec495_session.h"
#include "device/modbus_session.h"
#include "workspace/device_workspace.h"
#include "attitude/heading_dial.h"
#include "configuration/hec495_settings_panel.h"
#include "record/replay_session.h"
#include "bus/register_browser.h"
#include "recording/replay_controls.h"
#include "sim/can_simulator.h"
#include "sim/hec495_simulator.h"
#include "sim/modbus_simulator.h"
#include "sim/pty_simulator.h"

#include <QDockWidget>
#include <QFileInfo>
#include <QScrollArea>

namespace imudesk::ui {

namespace {

QDockWidget *makeDock(QWidget *content, const QString &objectName, const QString &title)
{
    auto *dock = new QDockWidget(title);
    dock->setObjectName(objectName);
    dock->setWidget(content);
    return dock;
}

// Tools > Calibrate > HEC495 compass: the compass's own calibration methods (serial link).
void offerCompassCalibration(DeviceWorkspace &ws, device::Hec495Session *session)
{
    ws.offerTool(DeviceWorkspace::LinkTool::CompassCalibration, [&ws, session](QWidget *parent) {
        auto *wizard = new Hec495CalibrationWizard(*session, parent);
        if (ws.identity())
            wizard->runSaver().setIdentity(*ws.identity());
        wizard->setAttribute(Qt::WA_DeleteOnClose);
        // The wizard needs its session: it closes when the link goes.
        QObject::connect(session, &QObject::destroyed, wizard, &QWidget::close);
        wizard->show();
    });
}

} // namespace

bool LinkFactory::connectHec495(DeviceWorkspace &ws, const QString &port, int baud, int address, QString *error,
                                std::shared_ptr<void> keepAlive)
{
    auto link = std::make_unique<device::Hec495Session>();
    device::Hec495Session *session = link.get();
    const QString target = keepAlive ? tr("Simulated HEC495") : tr("HEC495 on %1").arg(port);
    if (!ws.attachLink(std::move(link), target, std::move(keepAlive))) {
        if (error)
            *error = tr("Disconnect first, then connect to the compass.");
        return false;
    }
    // The compass dial (heading, pitch, roll from the newest sample) and the settings.
    auto *dial = new HeadingDial;
    dial->setObjectName(QStringLiteral("headingDial"));
    QObject::connect(&ws, &DeviceWorkspace::viewTick, dial, [dial, session] {
        if (const auto s = session->store().latest(); s && s->has(model::FieldEuler))
            dial->setAttitude(s->yaw, s->pitch, s->roll);
    });
    ws.addLinkDock(makeDock(dial, QStringLiteral("headingDialDock"), tr("Compass")),
                   DeviceWorkspace::LinkDockPlace::OverAttitude);
    auto *panel = new Hec495SettingsPanel(session);
    panel->setObjectName(QStringLiteral("hec495SettingsPanel"));
    ws.addLinkDock(makeDock(panel, QStringLiteral("hec495SettingsDock"), tr("Compass settings")),
                   DeviceWorkspace::LinkDockPlace::BehindValues);
    offerCompassCalibration(ws, session);
    session->open(port, baud, address);
    return true;
}

bool LinkFactory::connectSimulatedHec495(DeviceWorkspace &ws, sim::Motion motion, QString *error)
{
    sim::Hec495Options options;
    options.motion = motion;
    options.rateHz = 50;
    auto simulator = std::make_shared<sim::PtySimulator>(std::make_unique<sim::Hec495Simulator>(options));
    QString why;
    if (!simulator->start(&why)) {
        if (error)
            *error = tr("The simulated compass could not start: %1").arg(why);
        return false;
    }
    const QString path = simulator->devicePath();
    return connectHec495(ws, path, options.baud, options.address, error, simulator);
}

bool LinkFactory::connectModbus(DeviceWorkspace &ws, device::ModbusOptions options, bool simulate, sim::Motion motion,
                                QString *error)
{
    std::shared_ptr<sim::ModbusSimulator> simulator;
    QString target = options.port;
    if (simulate) {
        sim::ModbusSimOptions so;
        so.kind = options.kind;
        so.nodeId = options.nodeId;
        so.baud = options.baud;
        so.motion = motion;
        simulator = std::make_shared<sim::ModbusSimulator>(so);
        QString why;
        if (!simulator->start(&why)) {
            if (error)
                *error = tr("The simulated Modbus device could not start: %1").arg(why);
            return false;
        }
        options.port = simulator->devicePath();
        target = options.kind == protocol::modbus::DeviceKind::Hec495 ? tr("Simulated HEC495 (Modbus)")
                                                                       : tr("Simulated HI14 (Modbus)");
    }
    auto link = std::make_unique<device::ModbusSession>();
    device::ModbusSession *session = link.get();
    if (!ws.attachLink(std::move(link), tr("%1, Modbus node %2").arg(target).arg(options.effectiveNodeId()), simulator)) {
        if (error)
            *error = tr("Disconnect first, then connect to the Modbus device.");
        return false;
    }
    ws.addLinkDock(new RegisterBrowser(session), DeviceWorkspace::LinkDockPlace::BehindValues);
    ws.offerTool(DeviceWorkspace::LinkTool::ScanBus, [session](QWidget *parent) {
        auto *dialog = new ModbusScanDialog(session, parent);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->open();
    });
    session->open(options);
    return true;
}

bool LinkFactory::connectCan(DeviceWorkspace &ws, const device::CanSessionOptions &options, bool simulate,
                             sim::Motion motion, QString *error)
{
    std::shared_ptr<sim::CanSimulator> simulator;
    if (simulate) {
        sim::CanSimOptions so;
        so.hec495 = options.protocol == protocol::can::CanProtocol::Hec495;
        // The simulated HEC495 speaks standard frames on a "CANopen" bus, the extended variant
        // (0x18FA....) on a "J1939" one (CanSimOptions).
        const bool standardFrames = options.protocol == protocol::can::CanProtocol::CanOpen
                                 || (so.hec495 && !options.hec495Extended);
        so.protocol = standardFrames ? protocol::can::CanProtocol::CanOpen : protocol::can::CanProtocol::J1939;
        so.node = options.node;
        so.motion = motion;
        simulator = std::make_shared<sim::CanSimulator>(so);
        QString why;
        if (!simulator->start(options.plugin, options.interfaceName, &why)) {
            if (error)
                *error = tr("The simulated CAN device could not start on %1:%2: %3")
                             .arg(options.plugin, options.interfaceName, why);
            return false;
        }
    }
    auto link = std::make_unique<device::CanSession>();
    device::CanSession *session = link.get();
    const QString target = tr("CAN %1:%2").arg(options.plugin, options.interfaceName);
    if (!ws.attachLink(std::move(link), target, simulator)) {
        if (error)
            *error = tr("Disconnect first, then connect to the CAN bus.");
        return false;
    }
    auto *monitor = new CanMonitorWidget;
    monitor->setObjectName(QStringLiteral("canMonitor"));
    QObject::connect(session, &device::CanSession::framesSeen, monitor, &CanMonitorWidget::addEvents);
    QObject::connect(monitor, &CanMonitorWidget::sendFrameRequested, session, &device::CanSession::sendFrame);
    ws.addLinkDock(makeDock(monitor, QStringLiteral("canMonitorDock"), tr("CAN frames")),
                   DeviceWorkspace::LinkDockPlace::Below);
    auto *panel = new CanConfigPanel;
    panel->setObjectName(QStringLiteral("canConfigPanel"));
    panel->setSession(session);
    QObject::connect(session, &QObject::destroyed, panel, [panel] { panel->setSession(nullptr); });
    // The form is taller than the values it sits behind: on a short screen (1366x768 in
    // Chinese) it scrolls, rather than making the window taller than the screen.
    auto *scroll = new QScrollArea;
    scroll->setObjectName(QStringLiteral("canConfigScroll"));
    scroll->setWidget(panel);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setMinimumWidth(panel->minimumSizeHint().width());
    ws.addLinkDock(makeDock(scroll, QStringLiteral("canConfigDock"), tr("CAN configuration")),
                   DeviceWorkspace::LinkDockPlace::BehindValues);
    if (options.protocol == protocol::can::CanProtocol::CanOpen) {
        // A HiPNUC module on CANopen updates over the bus: the session stays on it, the dialog
        // talks to the node with its own CAN device (SDO to 0x1F51), and the session sees the
        // module leave and come back.
        ws.offerTool(DeviceWorkspace::LinkTool::FirmwareUpdate, [&ws, session](QWidget *parent) {
            auto *dialog = new FirmwareUpdateDialog(QString(), 0, ws.identity(), parent);
            dialog->setAttribute(Qt::WA_DeleteOnClose);
            dialog->setLink(FirmwareUpdateDialog::Link::Can);
            const auto &o = session->options();
            dialog->setCanBus(o.plugin, o.interfaceName, o.bitrate, session->targetNode() > 0 ? session->targetNode() : 8);
            dialog->open();
        });
    }
    session->open(options);
    return true;
}

bool LinkFactory::openReplay(DeviceWorkspace &ws, const QString &path, QString *error)
{
    if (!QFileInfo(path).isReadable()) {
        if (error)
            *error = tr("%1 cannot be read. Check that the file exists and that you may read it.").arg(path);
        return false;
    }
    auto link = std::make_unique<record::ReplaySession>();
    record::ReplaySession *session = link.get();
    if (!ws.attachLink(std::move(link), tr("Replay of %1").arg(QFileInfo(path).fileName()))) {
        if (error)
            *error = tr("Disconnect first, then open the capture.");
        return false;
    }
    auto *controls = new ReplayControls;
    controls->setObjectName(QStringLiteral("replayControls"));
    controls->setSession(session);
    ws.addLinkDock(makeDock(controls, QStringLiteral("replayDock"), tr("Replay")), DeviceWorkspace::LinkDockPlace::Below);
    // A capture plays as soon as it is open, as a recording would on a player: the views fill
    // at once; Pause, seek and speed are in the Replay panel.
    QObject::connect(session, &record::ReplaySession::opened, session, [session] { session->play(); },
                     Qt::SingleShotConnection);
    session->open(path);
    return true;
}

} // namespace imudesk::ui
