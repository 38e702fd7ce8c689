#include "can_firmware_updater.h"

#include "firmware/qt_can_frame_link.h"

#include <QLoggingCategory>
#include <QMetaObject>
#include <QThread>

namespace imudesk::firmware {

namespace {
Q_LOGGING_CATEGORY(lcCanUpdater, "imudesk.core.firmware.canupdater", QtInfoMsg)
}

CanFirmwareUpdater::CanFirmwareUpdater(QObject *parent) : QObject(parent) {}

CanFirmwareUpdater::~CanFirmwareUpdater()
{
    if (m_thread) {
        cancel();
        m_thread->wait();
        delete m_thread;
        m_thread = nullptr;
    }
}

bool CanFirmwareUpdater::start(const Bus &bus, const protocol::ihex::FirmwareImage &image,
                               const CanUpdateFlow::Options &options)
{
    if (m_thread)
        return false;
    m_result = {};
    m_shared = std::make_shared<Shared>();
    auto shared = m_shared;
    auto result = std::make_shared<CanUpdateFlow::Result>();
    // The link (QCanBusDevice) and the flow are made in the worker thread; the observer's
    // callbacks reach this object's thread as queued signals.
    m_thread = QThread::create([this, bus, image, options, shared, result] {
        QtCanFrameLink link(bus.plugin, bus.interfaceName, bus.bitrate);
        CanUpdateFlow::Observer obs;
        obs.stateChanged = [this](CanUpdateFlow::State s) { Q_EMIT stateChanged(int(s), CanUpdateFlow::stateName(s)); };
        obs.progress = [this](uint64_t done, uint64_t total, double rate, double left) {
            Q_EMIT progressChanged(done, total, rate, left);
        };
        obs.log = [this](const QString &line) { Q_EMIT logMessage(line); };
        auto flow = std::make_shared<CanUpdateFlow>(link, options, std::move(obs));
        std::atomic_store(&shared->flow, flow);
        if (shared->cancel)
            flow->cancel();
        *result = flow->run(image);
        link.close();
        std::atomic_store(&shared->flow, std::shared_ptr<CanUpdateFlow>());
        QMetaObject::invokeMethod(this, [this, result] { m_result = *result; }, Qt::QueuedConnection);
    });
    m_thread->setObjectName(QStringLiteral("can-firmware-update"));
    connect(m_thread, &QThread::finished, this, &CanFirmwareUpdater::onWorkerDone);
    m_thread->start();
    qCInfo(lcCanUpdater) << "CAN update on" << bus.plugin << bus.interfaceName << "node" << options.node << "started";
    return true;
}

void CanFirmwareUpdater::cancel()
{
    if (!m_shared)
        return;
    m_shared->cancel = true;
    if (auto flow = std::atomic_load(&m_shared->flow))
        flow->cancel();
}

void CanFirmwareUpdater::onWorkerDone()
{
    if (!m_thread)
        return;
    m_thread->wait();
    delete m_thread;
    m_thread = nullptr;
    m_shared.reset();
    Q_EMIT finished(m_result.ok, m_result.message);
}

} // namespace imudesk::firmware
