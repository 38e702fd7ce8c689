#include "families/built_in_families.h"

#include "attitude/heading_dial.h"
#include "calibration/hec495_calibration_wizard.h"
#include "charts/chart_panel.h"
#include "configuration/hec495_settings_panel.h"
#include "device/hec495_session.h"
#include "model/attitude.h"
#include "workspace/device_workspace.h"

#include <QDockWidget>

namespace imudesk::ui {

bool Hec495SerialUi::accepts(const device::DeviceLink &link) const
{
    return qobject_cast<const device::Hec495Session *>(&link) != nullptr;
}

QString Hec495SerialUi::target(const device::LinkRequest &request) const
{
    return request.simulate ? tr("Simulated HEC495") : tr("HEC495 on %1").arg(request.address);
}

namespace {
const QString kModel = QStringLiteral("HEC495");
} // namespace

std::vector<SimulatedDevice> Hec495SerialUi::simulatedDevices() const
{
    return {{PortChoice::simulated(kModel, QString()), tr("Simulated HEC495 compass")}};
}

std::optional<device::LinkRequest> Hec495SerialUi::simulatedRequest(const PortChoice &choice,
                                                                    const SimulationSetup &setup) const
{
    if (choice.kind != PortChoice::Kind::Simulated || choice.model != kModel)
        return std::nullopt;
    return device::LinkRequest::simulatedHec495(setup.motion);
}

std::optional<PortChoice> Hec495SerialUi::simulatedChoice(const device::LinkRequest &request) const
{
    if (!request.simulate || request.kind != device::LinkRequest::Kind::Serial || request.family != QLatin1String("hec495"))
        return std::nullopt;
    return PortChoice::simulated(kModel, QString());
}

void Hec495SerialUi::decorate(DeviceWorkspace &ws, device::DeviceLink &link, const device::LinkRequest &) const
{
    auto *session = static_cast<device::Hec495Session *>(&link);
    // The compass dial (heading, pitch, roll from the newest sample) and the settings.
    auto *dial = new HeadingDial;
    dial->setObjectName(QStringLiteral("headingDial"));
    QObject::connect(&ws, &DeviceWorkspace::viewTick, dial, [dial, session] {
        if (const auto s = session->store().latest(); s && s->has(model::FieldEuler))
            dial->setAttitude(s->has(model::FieldHeading) ? s->headingDeg : model::wrap360(-s->yaw), s->pitch, s->roll);
    });
    ws.addLinkDock(familyDock(dial, QStringLiteral("headingDialDock"), tr("Compass")),
                   DeviceWorkspace::LinkDockPlace::OverAttitude);
    auto *panel = new Hec495SettingsPanel(session);
    panel->setObjectName(QStringLiteral("hec495SettingsPanel"));
    ws.addLinkDock(familyDock(panel, QStringLiteral("hec495SettingsDock"), tr("Compass settings")),
                   DeviceWorkspace::LinkDockPlace::BehindValues);
    // Streaming its default content (the 0x84 angles), the compass sends no acceleration or
    // rate: those charts say so, with a switch of the output content to all data (0x49 02, the
    // 0x14 record: angles, acceleration, rate, the relative field, the magnetic roll and its
    // clock). Not saved: the compass settings' Save keeps it over a restart.
    ws.chartPanel()->offerOutputSwitch(
        (1u << int(ChartKind::Accelerometer)) | (1u << int(ChartKind::Gyroscope))
            | (1u << int(ChartKind::MagneticRelative)),
        [] { return tr("Switch the output to all data"); },
        [session] { session->setOutputContent(protocol::witlink::OutputContent::AllData); });
    // Tools > Calibrate > HEC495 compass: the compass's own calibration methods.
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

} // namespace imudesk::ui
