#include "firmware_updater.h"

#include "core/firmware/serial_byte_link.h"

#include <QLoggingCategory>

namespace imudesk::firmware {

namespace {
Q_LOGGING_CATEGORY(lcUpdater, "imudesk.core.firmware.updater", QtInfoMsg)
}

FirmwareUpdater::FirmwareUpdater(QObject *parent) : UpdateRunner(parent) {}

bool FirmwareUpdater::start(const QString &portName, const protocol::ihex::FirmwareImage &image,
                            const UpdateFlow::Options &options)
{
    if (isRunning())
        return false;
    m_result = {};
    // The link (QSerialPort) and the flow are made in the worker thread; the observer's
    // callbacks reach this object's thread as queued signals.
    auto job = [this, portName, image, options](const RegisterCancel &registerCancel) {
        SerialByteLink link(portName);
        auto obs = signallingObserver<UpdateFlow>();
        obs.progress = [this](const UpdateFlow::Progress &p) {
            Q_EMIT progressChanged(p.done, p.total, p.bytesPerSecond, p.secondsLeft);
        };
        const Outcome outcome =
            runFlow(registerCancel, std::make_shared<UpdateFlow>(link, options, std::move(obs)), image, m_result);
        link.close();
        return outcome;
    };
    if (!launch(QStringLiteral("firmware-update"), std::move(job)))
        return false;
    qCInfo(lcUpdater) << "update on" << portName << "started";
    return true;
}

} // namespace imudesk::firmware
