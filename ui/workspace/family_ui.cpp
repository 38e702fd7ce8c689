#include "workspace/family_ui.h"

#include "workspace/device_workspace.h"

#include <QCoreApplication>

namespace imudesk::ui {

namespace {
struct Texts {
    Q_DECLARE_TR_FUNCTIONS(FamilyUi)
};
} // namespace

bool FamilyUi::attach(DeviceWorkspace &ws, device::LinkOpener::Opened &opened, const device::LinkRequest &request,
                      QString *error) const
{
    if (ws.attachLink(std::move(opened.link), target(request), std::move(opened.keepAlive), std::move(opened.start),
                      request.address))
        return true;
    if (error)
        *error = Texts::tr("Disconnect first, then connect to %1.").arg(target(request));
    return false;
}

const FamilyUi *FamilyUiRegistry::forLink(const device::DeviceLink &link) const
{
    for (const auto &f : m_families)
        if (f->accepts(link))
            return f.get();
    return nullptr;
}

std::vector<SimulatedDevice> FamilyUiRegistry::simulatedDevices() const
{
    std::vector<SimulatedDevice> all;
    for (const auto &f : m_families)
        for (SimulatedDevice &d : f->simulatedDevices())
            all.push_back(std::move(d));
    return all;
}

std::optional<device::LinkRequest> FamilyUiRegistry::simulatedRequest(const PortChoice &choice,
                                                                      const SimulationSetup &setup) const
{
    for (const auto &f : m_families)
        if (auto r = f->simulatedRequest(choice, setup))
            return r;
    return std::nullopt;
}

std::optional<PortChoice> FamilyUiRegistry::simulatedChoice(const device::LinkRequest &request) const
{
    for (const auto &f : m_families)
        if (auto c = f->simulatedChoice(request))
            return c;
    return std::nullopt;
}

bool showLink(DeviceWorkspace &ws, const FamilyUiRegistry &families, device::LinkOpener::Opened opened,
              const device::LinkRequest &request, QString *error)
{
    if (!opened.link) {
        if (error && error->isEmpty())
            *error = Texts::tr("Nothing was opened.");
        return false;
    }
    const FamilyUi *family = families.forLink(*opened.link);
    if (!family) {
        if (error)
            *error = Texts::tr("%1 answered, but ImuDesk has no view for its family.").arg(request.address);
        return false;
    }
    device::DeviceLink *link = opened.link.get();
    if (!family->attach(ws, opened, request, error))
        return false;
    family->decorate(ws, *link, request);
    ws.startLink();
    return true;
}

bool openLinkIn(DeviceWorkspace &ws, const FamilyUiRegistry &families, device::LinkRequest request, QString *error)
{
    if (ws.isBusy()) {
        // Before anything starts (a simulator, a bus): the workspace cannot take it.
        if (error)
            *error = Texts::tr("Disconnect first, then connect again.");
        return false;
    }
    device::LinkOpener::Opened opened = device::LinkOpener::openNow(request, error);
    if (!opened.link)
        return false;
    return showLink(ws, families, std::move(opened), request, error);
}

} // namespace imudesk::ui
