#include "firmware_updater.h"

#include "firmware/serial_byte_link.h"

#include <QLoggingCategory>
#include <QMetaObject>
#include <QThread>

namespace imudesk::firmware {

namespace {
Q_LOGGING_CATEGORY(lcUpdater, "imudesk.core.firmware.updater", QtInfoMsg)
}

FirmwareUpdater::FirmwareUpdater(QObject *parent) : QObject(parent) {}

FirmwareUpdater::~FirmwareUpdater()
{
    if (m_thread) {
        cancel();
        m_thread->wait();
        delete m_thread;
        m_thread = nullptr;
    }
}

bool FirmwareUpdater::start(const QString &portName, const protocol::ihex::FirmwareImage &image,
                            const UpdateFlow::Options &options)
{
    if (m_thread)
        return false;
    m_result = {};
    m_shared = std::make_shared<Shared>();
    auto shared = m_shared;
    auto result = std::make_shared<UpdateFlow::Result>();
    // The link (QSerialPort) and the flow are made in the worker thread; the observer's
    // callbacks reach this object's thread as queued signals.
    m_thread = QThread::create([this, portName, image, options, shared, result] {
        SerialByteLink link(portName);
        UpdateFlow::Observer obs;
        obs.stateChanged = [this](UpdateFlow::State s) { Q_EMIT stateChanged(int(s), UpdateFlow::stateName(s)); };
        obs.progress = [this](const UpdateFlow::Progress &p) {
            Q_EMIT progressChanged(p.done, p.total, p.bytesPerSecond, p.secondsLeft);
        };
        obs.log = [this](const QString &line) { Q_EMIT logMessage(line); };
        auto flow = std::make_shared<UpdateFlow>(link, options, std::move(obs));
        std::atomic_store(&shared->flow, flow);
        if (shared->cancel)
            flow->cancel();
        *result = flow->run(image);
        link.close();
        std::atomic_store(&shared->flow, std::shared_ptr<UpdateFlow>());
        QMetaObject::invokeMethod(this, [this, result] { m_result = *result; }, Qt::QueuedConnection);
    });
    m_thread->setObjectName(QStringLiteral("firmware-update"));
    connect(m_thread, &QThread::finished, this, &FirmwareUpdater::onWorkerDone);
    m_thread->start();
    qCInfo(lcUpdater) << "update on" << portName << "started";
    return true;
}

void FirmwareUpdater::cancel()
{
    if (!m_shared)
        return;
    m_shared->cancel = true;
    if (auto flow = std::atomic_load(&m_shared->flow))
        flow->cancel();
}

void FirmwareUpdater::onWorkerDone()
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
