// HipnucSerialFamily: the baud-rate detection, the safe baud change and the link recovery
// after a reset, all as BaudScan plans. The rest of the family is in hipnuc_family.cpp.
#include "hipnuc_family.h"

#include "device/session_engine.h"

#include <QLoggingCategory>

#include <algorithm>

Q_DECLARE_LOGGING_CATEGORY(lcEngine)

namespace imudesk::device {

namespace hp = protocol::hipnuc;
using Outcome = BaudScan::Outcome;

namespace {
constexpr int kListenMs = 150;
constexpr int kDetectQueryTimeoutMs = 500;
constexpr int kProbeTimeoutMs = 700;
constexpr int kProbeAttempts = 2;
constexpr int kSerialConfigTimeoutMs = 1000;

bool unsent(const HipnucSerialFamily::Reply &r)
{
    using S = HipnucSerialFamily::Reply::Status;
    return r.status == S::Cancelled || r.status == S::NotSent;
}
} // namespace

// ---------------------------------------------------------------------------------------
// Detection: every rate of detectionBauds(), listening first

BaudScan::Plan HipnucSerialFamily::detectionPlan()
{
    BaudScan::Plan p;
    p.bauds = detectionBauds();
    p.listenMs = kListenMs; // a module that streams is recognised by a CRC-valid frame
    p.tune = [this](int baud) {
        engine().transport().setBaud(baud);
        engine().transport().clear();
        m_decoder.restart();
        m_found.reset();
        m_framesAtDetectStart = m_decoder.demux().frameCounters().frames;
        engine().setState(SessionState::Detecting, tr("trying %1 baud").arg(baud));
    };
    p.probe = [this](int, BaudScan::Answer answer) { detectQuery(false, std::move(answer)); };
    p.found = [this](int baud) {
        engine().setWorkingBaud(baud);
        engine().restartStatistics();
        Q_EMIT baudDetected(baud);
        const auto connected = [this, baud] {
            engine().setState(SessionState::Connected,
                              tr("%1 at %2 baud").arg(engine().transport().address()).arg(baud));
            finishLink(true, baud);
        };
        if (!m_found) {
            connected();
            return;
        }
        noteIdentity(*m_found);
        queryWorldFrame(connected); // the frame before "connected", as after a fixed-rate open
    };
    p.exhausted = [this] {
        engine().fail(tr("No HiPNUC device answered on %1 at any baud rate (115200, 921600, 460800, 230400, "
                         "256000, 57600, 38400, 19200, 9600, 4800). Check the cable and the power, and that "
                         "no other program uses the port.")
                          .arg(engine().transport().address()));
        finishLink(false, 0);
    };
    return p;
}

void HipnucSerialFamily::detectQuery(bool retry, BaudScan::Answer answer)
{
    engine().submit(makeRequest(hp::commands::logVersion(), kDetectQueryTimeoutMs, [this, retry, answer](const Reply &r) {
        if (takeIdentity(r)) {
            answer(Outcome::Found);
            return;
        }
        const bool sawFrames = m_decoder.demux().frameCounters().frames > m_framesAtDetectStart;
        if (sawFrames && !retry && m_scan.running())
            detectQuery(true, answer);
        else if (sawFrames)
            answer(Outcome::Found); // streams valid frames but does not answer
        else
            answer(unsent(r) ? Outcome::Stop : Outcome::TryNext);
    }));
}

// ---------------------------------------------------------------------------------------
// Baud change and recovery: LOG VERSION at a few rates, then the whole detection

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
        if (unsent(r)) {
            Q_EMIT baudChangeFinished(false, 0, QString::fromStdString(r.errorLine));
            return;
        }
        if (r.status == Reply::Status::Refused) {
            // Refused: the module keeps its rate. Confirm that it is still there.
            probeBauds({old}, [this, baud, old, r](bool reachable, int at) {
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
        probeBauds({baud, old}, [this, baud, old](bool reachable, int at) {
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
        probeBauds(order, [this](bool reachable, int at) {
            if (reachable)
                m_coordChangePending = false; // the module was reset: its COORD is in effect now
            Q_EMIT linkRecovered(reachable, at,
                                 reachable ? tr("the device answers at %1 baud").arg(at)
                                           : tr("the device does not answer at any baud rate"));
        });
    });
}

void HipnucSerialFamily::probeBauds(std::vector<int> bauds, LinkDone done)
{
    finishLink(false, 0); // a recovery still under way has lost the link to this one
    if (!engine().transport().isOpen()) {
        done(false, 0);
        return;
    }
    m_linkDone = std::move(done);
    BaudScan::Plan p;
    p.bauds = std::move(bauds);
    p.tune = [this](int baud) {
        m_found.reset();
        if (engine().transport().baud() != baud)
            setHostBaud(baud);
    };
    p.probe = [this](int, BaudScan::Answer answer) { probeVersion(1, std::move(answer)); };
    p.found = [this](int baud) {
        engine().setWorkingBaud(baud);
        Q_EMIT baudDetected(baud);
        noteIdentity(*m_found);
        finishLink(true, baud);
    };
    p.exhausted = [this] {
        qCInfo(lcEngine) << "the device does not answer at the expected rates - auto-detecting";
        engine().setState(SessionState::Detecting, engine().transport().address());
        m_scan.start(detectionPlan());
    };
    p.stopped = [this] { finishLink(false, 0); };
    m_scan.start(std::move(p));
}

void HipnucSerialFamily::probeVersion(int attempt, BaudScan::Answer answer)
{
    if (!engine().transport().isOpen()) {
        answer(Outcome::Stop);
        return;
    }
    engine().submit(makeRequest(hp::commands::logVersion(), kProbeTimeoutMs, [this, attempt, answer](const Reply &r) {
        if (unsent(r)) {
            answer(Outcome::Stop);
            return;
        }
        if (takeIdentity(r)) {
            answer(Outcome::Found);
            return;
        }
        if (attempt < kProbeAttempts && m_scan.running())
            probeVersion(attempt + 1, answer);
        else
            answer(Outcome::TryNext);
    }));
}

bool HipnucSerialFamily::takeIdentity(const Reply &r)
{
    if (!r.ok())
        return false;
    const auto id = model::DeviceIdentity::fromKeyValues(r.values);
    if (!id.usable())
        return false;
    m_found = id;
    return true;
}

void HipnucSerialFamily::finishLink(bool reachable, int baud)
{
    if (LinkDone done = std::exchange(m_linkDone, {}))
        done(reachable, baud);
}

} // namespace imudesk::device
