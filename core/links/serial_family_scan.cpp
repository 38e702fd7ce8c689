#include "serial_family_scan.h"

#include "device/session_engine.h"

#include <QLoggingCategory>

#include <algorithm>

namespace imudesk::device {

namespace {

Q_LOGGING_CATEGORY(lcDetect, "imudesk.core.device.detect")

} // namespace

const SerialFamilyKind *SerialFamilyScan::classify(qsizetype newFrom)
{
    // Each byte goes through each family's recogniser once.
    for (auto &[family, recogniser] : m_recognisers)
        if (recogniser->recognise(m_held, newFrom, &m_seenAddress))
            return family;
    return nullptr;
}

SerialFamilyScan::SerialFamilyScan(std::vector<int> bauds, int deviceAddress)
    : m_bauds(bauds.empty() ? serialDetectionBauds() : std::move(bauds))
{
    for (const SerialFamilyKind *f : serialFamilies())
        m_query += f->query(deviceAddress);
    restartStream();
}

SerialFamilyScan::~SerialFamilyScan() = default;

int SerialFamilyScan::firstBaud(int requestedBaud) const
{
    return requestedBaud > 0 ? requestedBaud : m_bauds.front();
}

void SerialFamilyScan::opened(int requestedBaud)
{
    const QString port = engine().transport().address();
    engine().setState(SessionState::Detecting, port);
    BaudScan::Plan p;
    p.bauds = requestedBaud > 0 ? std::vector<int>{requestedBaud} : m_bauds;
    p.listenMs = kListenMs; // a device that streams is recognised before it is asked anything
    p.tune = [this](int baud) {
        engine().transport().setBaud(baud);
        engine().transport().clear();
        restartStream();
        engine().setState(SessionState::Detecting, tr("trying %1 baud").arg(baud));
    };
    p.probe = [this](int, BaudScan::Answer answer) {
        if (m_seen)
            answer(BaudScan::Outcome::Found); // it streamed while we listened
        else
            probe(std::move(answer), 0);
    };
    p.found = [this](int baud) {
        qCDebug(lcDetect) << baud << "baud:" << m_seen->id() << "address" << m_seenAddress;
        engine().setWorkingBaud(baud);
        Q_EMIT found(m_seen->id(), baud, m_seenAddress);
    };
    p.exhausted = [this, bauds = p.bauds, port] {
        QStringList rates;
        for (int b : bauds)
            rates << QString::number(b);
        QStringList families;
        for (const SerialFamilyKind *f : serialFamilies())
            families << f->displayName();
        engine().fail(tr("no device answered on %1 at %2 baud (looked for %3): check the power, the wiring and "
                         "that no other program holds the port")
                          .arg(port, rates.join(QLatin1Char('/')), families.join(tr(" or "))));
    };
    m_scan.start(std::move(p));
}

void SerialFamilyScan::probe(BaudScan::Answer answer, int attempt)
{
    Request r;
    r.wire = m_query;
    r.timeoutMs = kAnswerMs;
    r.done = [this, answer = std::move(answer), attempt](const RequestResult &res) {
        if (res.ok()) {
            answer(BaudScan::Outcome::Found);
        } else if (res.status == RequestStatus::Cancelled || res.status == RequestStatus::NotSent) {
            answer(BaudScan::Outcome::Stop);
        } else if (attempt == 0 && m_held.isEmpty()) {
            // Asked again when the line stayed silent: a query right after a rate change can
            // be lost (the first bytes after a UART changes speed).
            probe(answer, 1);
        } else {
            qCDebug(lcDetect) << engine().transport().baud() << "baud:" << m_held.size() << "bytes, no family";
            answer(BaudScan::Outcome::TryNext);
        }
    };
    engine().submit(std::move(r));
}

void SerialFamilyScan::stopping()
{
    m_scan.stop();
}

void SerialFamilyScan::restartStream()
{
    m_held.clear();
    m_recognisers.clear();
    for (const SerialFamilyKind *f : serialFamilies())
        m_recognisers.emplace_back(f, f->recogniser());
    m_seen = nullptr;
    m_seenAddress = -1;
}

void SerialFamilyScan::feed(const QByteArray &bytes, int64_t)
{
    m_bytesIn += quint64(bytes.size());
    m_heard += quint64(bytes.size());
    if (m_seen || m_held.size() >= kMaxHeld)
        return;
    const qsizetype before = m_held.size();
    m_held += bytes.left(kMaxHeld - before);
    m_seen = classify(before);
    if (m_seen && engine().current()) {
        RequestResult r;
        r.status = RequestStatus::Ok;
        r.reply = m_seen->id();
        engine().finishCurrent(std::move(r));
    }
}

void SerialFamilyScan::unanswered(const Request &, RequestResult &result)
{
    result.reply = QString();
}

} // namespace imudesk::device
