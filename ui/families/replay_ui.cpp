#include "families/built_in_families.h"

#include "record/replay_session.h"
#include "recording/replay_controls.h"
#include "workspace/device_workspace.h"

#include <QFileInfo>

namespace imudesk::ui {

bool ReplayUi::accepts(const device::DeviceLink &link) const
{
    return qobject_cast<const record::ReplaySession *>(&link) != nullptr;
}

QString ReplayUi::target(const device::LinkRequest &request) const
{
    return tr("Replay of %1").arg(QFileInfo(request.address).fileName());
}

void ReplayUi::decorate(DeviceWorkspace &ws, device::DeviceLink &link, const device::LinkRequest &) const
{
    auto *session = static_cast<record::ReplaySession *>(&link);
    auto *controls = new ReplayControls;
    controls->setObjectName(QStringLiteral("replayControls"));
    controls->setSession(session);
    ws.addLinkDock(familyDock(controls, QStringLiteral("replayDock"), tr("Replay")), DeviceWorkspace::LinkDockPlace::Below);
    // A capture plays as soon as it is open, as a recording would on a player: the views fill
    // at once; Pause, seek and speed are in the Replay panel.
    QObject::connect(session, &record::ReplaySession::opened, session, [session] { session->play(); },
                     Qt::SingleShotConnection);
}

} // namespace imudesk::ui
