#include "serial_family_scan.h"

#include "device/session_engine.h"
#include "protocol/witlink/commands.h"
#include "protocol/witlink/reply.h"

#include <QLoggingCategory>

#include <algorithm>

namespace imudesk::device {

namespace {

Q_LOGGING_CATEGORY(lcDetect, "imudesk.core.device.detect")

namespace wl = protocol::witlink;

QByteArray familyQuery(int hec495Address)
{
    QByteArray query = QByteArrayLiteral("LOG VERSION\r\n");
    for (const auto &frame : {wl::commands::readAll(uint8_t(hec495Address)), wl::commands::queryAddress()})
        query.append(reinterpret_cast<const char *>(frame.data()), qsizetype(frame.size()));
    query.append("\r\n");
    return query;
}

} // namespace

const char *serialFamilyName(SerialFamily f)
{
    switch (f) {
    case SerialFamily::Hipnuc: return "hipnuc";
    case SerialFamily::Hec495: return "hec495";
    case SerialFamily::Unknown: break;
    }
    return "unknown";
}

const std::vector<int> &SerialFamilyScan::defaultBauds()
{
    static const std::vector<int> bauds = {115200, 921600, 460800, 230400, 256000, 57600, 38400, 19200, 9600, 4800, 2400};
    return bauds;
}

SerialFamily SerialFamilyScan::classify(const QByteArray &bytes, qsizetype newFrom)
{
    const auto *p = reinterpret_cast<const uint8_t *>(bytes.constData()) + newFrom;
    const size_t n = size_t(bytes.size() - newFrom);
    // Each byte goes through the frame decoders once; they keep an unfinished frame between calls.
    if (!m_hipnucFrames.feed(p, n).empty())
        return SerialFamily::Hipnuc;
    // A HiPNUC reply line ("OK", or the KEY=VALUE lines of LOG VERSION), looked for where the new
    // bytes may complete one.
    const qsizetype from = std::max<qsizetype>(0, newFrom - 5);
    if (bytes.indexOf("\r\nOK\r\n", from) >= 0 || bytes.startsWith("OK\r\n") || bytes.indexOf("PNAME=", from) >= 0)
        return SerialFamily::Hipnuc;
    for (const auto &f : m_witlinkFrames.feed(p, n)) {
        const wl::Reply r = wl::decodeReply(f);
        if (!r.ok())
            continue;
        if (r.kind == wl::Reply::Kind::AllData || r.kind == wl::Reply::Kind::Angles
            || r.kind == wl::Reply::Kind::Address) {
            m_seenAddress = r.kind == wl::Reply::Kind::Address ? r.deviceAddress : r.address;
            return SerialFamily::Hec495;
        }
    }
    return SerialFamily::Unknown;
}

SerialFamilyScan::SerialFamilyScan(std::vector<int> bauds, int hec495Address)
    : m_bauds(bauds.empty() ? defaultBauds() : std::move(bauds)), m_hec495Address(hec495Address)
{
    qRegisterMetaType<SerialFamily>();
}

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
        if (m_seen != SerialFamily::Unknown)
            answer(BaudScan::Outcome::Found); // it streamed while we listened
        else
            probe(std::move(answer), 0);
    };
    p.found = [this](int baud) {
        qCDebug(lcDetect) << baud << "baud:" << serialFamilyName(m_seen) << "address" << m_seenAddress;
        engine().setWorkingBaud(baud);
        Q_EMIT found(m_seen, baud, m_seen == SerialFamily::Hec495 ? m_seenAddress : -1);
    };
    p.exhausted = [this, bauds = p.bauds, port] {
        QStringList rates;
        for (int b : bauds)
            rates << QString::number(b);
        engine().fail(tr("neither a HiPNUC module nor an HEC495 answered on %1 at %2 baud: check the power, the "
                         "wiring and that no other program holds the port")
                          .arg(port, rates.join(QLatin1Char('/'))));
    };
    m_scan.start(std::move(p));
}

void SerialFamilyScan::probe(BaudScan::Answer answer, int attempt)
{
    Request r;
    r.wire = familyQuery(m_hec495Address);
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
    m_hipnucFrames.reset();
    m_witlinkFrames.reset();
    m_seen = SerialFamily::Unknown;
    m_seenAddress = -1;
}

void SerialFamilyScan::feed(const QByteArray &bytes, int64_t)
{
    m_bytesIn += quint64(bytes.size());
    if (m_seen != SerialFamily::Unknown || m_held.size() >= kMaxHeld)
        return;
    const qsizetype before = m_held.size();
    m_held += bytes.left(kMaxHeld - before);
    m_seen = classify(m_held, before);
    if (m_seen != SerialFamily::Unknown && engine().current()) {
        RequestResult r;
        r.status = RequestStatus::Ok;
        r.reply = QVariant::fromValue(m_seen);
        engine().finishCurrent(std::move(r));
    }
}

void SerialFamilyScan::unanswered(const Request &, RequestResult &result)
{
    result.reply = QVariant::fromValue(SerialFamily::Unknown);
}

} // namespace imudesk::device
