// SessionWorker: the safe baud change and the link recovery after a reset. The rest of the
// worker is in session_worker.cpp.
#include "session_worker.h"
#include "protocol/hipnuc/ascii_command.h"

#include "device/device_session.h"

#include <QLoggingCategory>
#include <QTimer>

#include <algorithm>

Q_DECLARE_LOGGING_CATEGORY(lcSession)

namespace imudesk::device {

namespace {
constexpr int kProbeTimeoutMs = 700;
constexpr int kProbeAttempts = 2;
constexpr int kSerialConfigTimeoutMs = 1000;
} // namespace

void SessionWorker::changeBaud(int baud)
{
    if (!m_transport || !m_transport->isOpen()) {
        Q_EMIT baudChangeFinished(false, 0, tr("the port is not open"));
        return;
    }
    const int old = m_transport->baud();
    Pending p;
    p.text = QStringLiteral("SERIALCONFIG %1").arg(baud);
    p.timeoutMs = kSerialConfigTimeoutMs;
    p.done = [this, baud, old](const Reply &r) {
        if (r.status == Reply::Status::Cancelled || r.status == Reply::Status::NotSent) {
            Q_EMIT baudChangeFinished(false, 0, QString::fromStdString(r.errorLine));
            return;
        }
        if (r.status == Reply::Status::Error) {
            // Refused: the module keeps its rate. Confirm that it is still there.
            probeBauds({old}, 0, 1, [this, old, r](bool reachable, int at) {
                Q_EMIT baudChangeFinished(false, reachable ? at : 0,
                                          tr("the device refused SERIALCONFIG %1 (%2) and stays at %3 baud")
                                              .arg(QString::fromStdString(r.command).section(QLatin1Char(' '), 1))
                                              .arg(QString::fromStdString(r.errorLine))
                                              .arg(old));
            });
            return;
        }
        // OK was sent at the old rate and the module has switched (or, on a timeout, may have).
        qCInfo(lcSession) << "SERIALCONFIG" << baud << (r.ok() ? "acknowledged" : "unanswered") << "- following";
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
    };
    enqueue(std::move(p));
}

void SessionWorker::recoverLink(const QList<int> &bauds, int settleMs)
{
    if (!m_transport || !m_transport->isOpen()) {
        Q_EMIT linkRecovered(false, 0, tr("the port is not open"));
        return;
    }
    std::vector<int> order;
    for (int b : bauds)
        if (b > 0 && std::find(order.begin(), order.end(), b) == order.end())
            order.push_back(b);
    if (std::find(order.begin(), order.end(), m_transport->baud()) == order.end())
        order.push_back(m_transport->baud());
    QTimer::singleShot(std::max(0, settleMs), this, [this, order] {
        probeBauds(order, 0, 1, [this](bool reachable, int at) {
            Q_EMIT linkRecovered(reachable, at,
                                 reachable ? tr("the device answers at %1 baud").arg(at)
                                           : tr("the device does not answer at any baud rate"));
        });
    });
}

void SessionWorker::probeBauds(std::vector<int> bauds, size_t index, int attempt, LinkDone done)
{
    if (!m_transport || !m_transport->isOpen()) {
        done(false, 0);
        return;
    }
    if (index >= bauds.size()) {
        detectForRecovery(std::move(done));
        return;
    }
    const int baud = bauds[index];
    if (m_transport->baud() != baud)
        setHostBaud(baud);
    Pending p;
    p.text = QString::fromStdString(protocol::hipnuc::commands::logVersion().text);
    p.timeoutMs = kProbeTimeoutMs;
    p.done = [this, bauds = std::move(bauds), index, attempt, baud, done = std::move(done)](const Reply &r) mutable {
        if (r.status == Reply::Status::Cancelled || r.status == Reply::Status::NotSent) {
            done(false, 0);
            return;
        }
        if (r.ok()) {
            const auto id = model::DeviceIdentity::fromKeyValues(r.values);
            if (id.usable()) {
                m_workingBaud = baud;
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
    };
    enqueue(std::move(p));
}

void SessionWorker::detectForRecovery(LinkDone done)
{
    qCInfo(lcSession) << "the device does not answer at the expected rates - auto-detecting";
    m_afterDetect = std::move(done);
    m_detecting = true;
    setState(SessionState::Detecting, m_portName);
    detectAt(0);
}

} // namespace imudesk::device
