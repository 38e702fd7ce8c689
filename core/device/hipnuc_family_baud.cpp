// HipnucSerialFamily: the baud-rate detection, the safe baud change and the link recovery
// after a reset. The rest of the family is in hipnuc_family.cpp.
#include "hipnuc_family.h"

#include "device/session_engine.h"

#include <QLoggingCategory>

#include <algorithm>

Q_DECLARE_LOGGING_CATEGORY(lcEngine)

namespace imudesk::device {

namespace hp = protocol::hipnuc;

namespace {
constexpr int kListenMs = 150;
constexpr int kDetectQueryTimeoutMs = 500;
constexpr int kProbeTimeoutMs = 700;
constexpr int kProbeAttempts = 2;
constexpr int kSerialConfigTimeoutMs = 1000;
} // namespace

// ---------------------------------------------------------------------------------------
// Detection

void HipnucSerialFamily::detectAt(size_t index)
{
    const auto &bauds = detectionBauds();
    if (!m_detecting)
        return;
    if (index >= bauds.size()) {
        m_detecting = false;
        engine().fail(tr("No HiPNUC device answered on %1 at any baud rate (115200, 921600, 460800, 230400, "
                         "256000, 57600, 38400, 19200, 9600, 4800). Check the cable and the power, and that "
                         "no other program uses the port.")
                          .arg(engine().transport().address()));
        if (LinkDone done = std::exchange(m_afterDetect, {}))
            done(false, 0);
        return;
    }
    m_detectIndex = index;
    engine().transport().setBaud(bauds[index]);
    engine().transport().clear();
    m_demux.reset();
    m_framesAtDetectStart = m_demux.frameCounters().frames;
    engine().setState(SessionState::Detecting, tr("trying %1 baud").arg(bauds[index]));
    // Listen first: a module that streams is recognised by a CRC-valid frame.
    m_detectTimer.disconnect();
    connect(&m_detectTimer, &QTimer::timeout, this, [this] { detectQuery(false); });
    m_detectTimer.start(kListenMs);
}

void HipnucSerialFamily::detectQuery(bool retry)
{
    if (!m_detecting)
        return;
    const size_t index = m_detectIndex;
    engine().submit(makeRequest(hp::commands::logVersion(), kDetectQueryTimeoutMs, [this, retry, index](const Reply &r) {
        if (!m_detecting || index != m_detectIndex)
            return;
        const int baud = detectionBauds()[index];
        if (r.ok()) {
            const auto id = model::DeviceIdentity::fromKeyValues(r.values);
            if (id.usable()) {
                detectFinished(baud, id);
                return;
            }
        }
        const bool sawFrames = m_demux.frameCounters().frames > m_framesAtDetectStart;
        if (sawFrames && !retry) {
            detectQuery(true);
            return;
        }
        if (sawFrames) {
            detectFinished(baud, std::nullopt); // streams valid frames but does not answer
            return;
        }
        if (r.status == Reply::Status::Cancelled || r.status == Reply::Status::NotSent)
            return;
        detectAt(index + 1);
    }));
}

void HipnucSerialFamily::detectFinished(int baud, const std::optional<model::DeviceIdentity> &id)
{
    m_detecting = false;
    engine().setWorkingBaud(baud);
    engine().restartStatistics();
    Q_EMIT baudDetected(baud);
    if (id)
        noteIdentity(*id);
    engine().setState(SessionState::Connected, tr("%1 at %2 baud").arg(engine().transport().address()).arg(baud));
    if (LinkDone done = std::exchange(m_afterDetect, {}))
        done(true, baud);
}

// ---------------------------------------------------------------------------------------
// Baud change and recovery

void HipnucSerialFamily::changeBaud(int baud)
{
    if (!engine().transport().isOpen()) {
        Q_EMIT baudChangeFinished(false, 0, tr("the port is not open"));
        return;
    }
    const hp::Command command = hp::commands::serialConfig(baud);
    if (!command.ok()) {
        Q_EMIT baudChangeFinished(false, 0, QString::fromStdString(command.error));
        return;
    }
    const int old = engine().transport().baud();
    engine().submit(makeRequest(command, kSerialConfigTimeoutMs, [this, baud, old](const Reply &r) {
        if (r.status == Reply::Status::Cancelled || r.status == Reply::Status::NotSent) {
            Q_EMIT baudChangeFinished(false, 0, QString::fromStdString(r.errorLine));
            return;
        }
        if (r.status == Reply::Status::Error) {
            // Refused: the module keeps its rate. Confirm that it is still there.
            probeBauds({old}, 0, 1, [this, baud, old, r](bool reachable, int at) {
                Q_EMIT baudChangeFinished(false, reachable ? at : 0,
                                          tr("the device refused SERIALCONFIG %1 (%2) and stays at %3 baud")
                                              .arg(baud)
                                              .arg(QString::fromStdString(r.errorLine))
                                              .arg(old));
            });
            return;
        }
        // OK was sent at the old rate and the module has switched (or, on a timeout, may have).
        qCInfo(lcEngine) << "SERIALCONFIG" << baud << (r.ok() ? "acknowledged" : "unanswered") << "- following";
        probeBauds({baud, old}, 0, 1, [this, baud, old](bool reachable, int at) {
            if (reachable && at == baud) {
                Q_EMIT baudChangeFinished(true, at, tr("the device answers at %1 baud").arg(at));
                return;
            }
            if (reachable)
                Q_EMIT baudChangeFinished(false, at,
                                          tr("the device did not answer at %1 baud; it answers at %2 baud")
                                              .arg(baud)
                                              .arg(at));
            else
                Q_EMIT baudChangeFinished(false, 0,
                                          tr("the device answers neither at %1 nor at %2 baud nor at any other rate: "
                                             "check the cable and power-cycle it")
                                              .arg(baud)
                                              .arg(old));
        });
    }));
}

void HipnucSerialFamily::recoverLink(const QList<int> &bauds, int settleMs)
{
    if (!engine().transport().isOpen()) {
        Q_EMIT linkRecovered(false, 0, tr("the port is not open"));
        return;
    }
    std::vector<int> order;
    for (int b : bauds)
        if (b > 0 && std::find(order.begin(), order.end(), b) == order.end())
            order.push_back(b);
    const int current = engine().transport().baud();
    if (std::find(order.begin(), order.end(), current) == order.end())
        order.push_back(current);
    QTimer::singleShot(std::max(0, settleMs), this, [this, order] {
        probeBauds(order, 0, 1, [this](bool reachable, int at) {
            Q_EMIT linkRecovered(reachable, at,
                                 reachable ? tr("the device answers at %1 baud").arg(at)
                                           : tr("the device does not answer at any baud rate"));
        });
    });
}

void HipnucSerialFamily::probeBauds(std::vector<int> bauds, size_t index, int attempt, LinkDone done)
{
    if (!engine().transport().isOpen()) {
        done(false, 0);
        return;
    }
    if (index >= bauds.size()) {
        detectForRecovery(std::move(done));
        return;
    }
    const int baud = bauds[index];
    if (engine().transport().baud() != baud)
        setHostBaud(baud);
    engine().submit(makeRequest(
        hp::commands::logVersion(), kProbeTimeoutMs,
        [this, bauds = std::move(bauds), index, attempt, baud, done = std::move(done)](const Reply &r) mutable {
            if (r.status == Reply::Status::Cancelled || r.status == Reply::Status::NotSent) {
                done(false, 0);
                return;
            }
            if (r.ok()) {
                const auto id = model::DeviceIdentity::fromKeyValues(r.values);
                if (id.usable()) {
                    engine().setWorkingBaud(baud);
                    Q_EMIT baudDetected(baud);
                    noteIdentity(id);
                    done(true, baud);
                    return;
                }
            }
            if (attempt < kProbeAttempts)
                probeBauds(std::move(bauds), index, attempt + 1, std::move(done));
            else
                probeBauds(std::move(bauds), index + 1, 1, std::move(done));
        }));
}

void HipnucSerialFamily::detectForRecovery(LinkDone done)
{
    qCInfo(lcEngine) << "the device does not answer at the expected rates - auto-detecting";
    m_afterDetect = std::move(done);
    m_detecting = true;
    engine().setState(SessionState::Detecting, engine().transport().address());
    detectAt(0);
}

} // namespace imudesk::device
