#include "can_firmware_updater.h"

#include "core/firmware/qt_can_frame_link.h"

#include <QLoggingCategory>

namespace imudesk::firmware {

namespace {
Q_LOGGING_CATEGORY(lcCanUpdater, "imudesk.core.firmware.canupdater", QtInfoMsg)
}

CanFirmwareUpdater::CanFirmwareUpdater(QObject *parent) : UpdateRunner(parent) {}

bool CanFirmwareUpdater::start(const Bus &bus, const protocol::ihex::FirmwareImage &image,
                               const CanUpdateFlow::Options &options)
{
    if (isRunning())
        return false;
    m_result = {};
    // The bus device (QCanBusDevice) and the flow are made in the worker thread.
    auto job = [this, bus, image, options](const RegisterCancel &registerCancel) {
        QtCanFrameLink link(bus.plugin, bus.interfaceName, bus.bitrate);
        auto obs = signallingObserver<CanUpdateFlow>();
        obs.progress = [this](uint64_t done, uint64_t total, double rate, double left) {
            Q_EMIT progressChanged(done, total, rate, left);
        };
        const Outcome outcome =
            runFlow(registerCancel, std::make_shared<CanUpdateFlow>(link, options, std::move(obs)), image, m_result);
        link.close();
        return outcome;
    };
    if (!launch(QStringLiteral("can-firmware-update"), std::move(job)))
        return false;
    qCInfo(lcCanUpdater) << "CAN update on" << bus.plugin << bus.interfaceName << "node" << options.node << "started";
    return true;
}

} // namespace imudesk::firmware
