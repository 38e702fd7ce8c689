#include "family_detector.h"

#include "io/serial_transport.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/witlink/commands.h"
#include "protocol/witlink/frame_decoder.h"
#include "protocol/witlink/reply.h"

#include <QElapsedTimer>
#include <QLoggingCategory>
#include <QSerialPort>

namespace imudesk::device {

namespace {

Q_LOGGING_CATEGORY(lcDetect, "imudesk.core.device.detect")

namespace wl = protocol::witlink;

QByteArray readFor(QSerialPort &port, int ms)
{
    QByteArray all;
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < ms) {
        if (port.waitForReadyRead(int(std::max<qint64>(1, ms - t.elapsed()))))
            all += port.readAll();
        // Bounded: a detection window at 921600 baud holds well under this.
        if (all.size() > 256 * 1024)
            break;
    }
    all += port.readAll();
    return all;
}

} // namespace

const std::vector<int> &FamilyDetector::defaultBauds()
{
    static const std::vector<int> bauds = {115200, 921600, 460800, 230400, 256000, 57600, 38400, 19200, 9600, 4800, 2400};
    return bauds;
}

const char *FamilyDetector::familyName(Family f)
{
    switch (f) {
    case Family::Hipnuc: return "hipnuc";
    case Family::Hec495: return "hec495";
    case Family::Unknown: break;
    }
    return "unknown";
}

FamilyDetector::Family FamilyDetector::classify(const QByteArray &bytes, int *hec495Address)
{
    const auto *p = reinterpret_cast<const uint8_t *>(bytes.constData());
    const size_t n = size_t(bytes.size());
    protocol::hipnuc::FrameDecoder hipnuc;
    if (!hipnuc.feed(p, n).empty())
        return Family::Hipnuc;
    // A HiPNUC reply line ("OK", or the KEY=VALUE lines of LOG VERSION).
    if (bytes.contains("\r\nOK\r\n") || bytes.startsWith("OK\r\n") || bytes.contains("PNAME="))
        return Family::Hipnuc;
    wl::FrameDecoder witlink;
    for (const auto &f : witlink.feed(p, n)) {
        const wl::Reply r = wl::decodeReply(f);
        if (!r.ok())
            continue;
        if (r.kind == wl::Reply::Kind::AllData || r.kind == wl::Reply::Kind::Angles
            || r.kind == wl::Reply::Kind::Address) {
            if (hec495Address)
                *hec495Address = r.kind == wl::Reply::Kind::Address ? r.deviceAddress : r.address;
            return Family::Hec495;
        }
    }
    return Family::Unknown;
}

FamilyDetector::Result FamilyDetector::detect(const QString &portName, const std::vector<int> &bauds, int hec495Address)
{
    Result res;
    QSerialPort port;
    port.setPortName(io::SerialTransport::systemLocation(portName));
    if (!port.open(QIODevice::ReadWrite)) {
        const auto kind = io::SerialTransport::classifyOpenError(int(port.error()),
                                                                 io::SerialTransport::isAccessible(portName));
        res.error = io::SerialTransport::describeOpenError(portName, kind, port.errorString());
        return res;
    }
    port.setDataBits(QSerialPort::Data8);
    port.setParity(QSerialPort::NoParity);
    port.setStopBits(QSerialPort::OneStop);
    port.setFlowControl(QSerialPort::NoFlowControl);
    QByteArray query = QByteArrayLiteral("LOG VERSION\r\n");
    for (const auto &frame : {wl::commands::readAll(uint8_t(hec495Address)), wl::commands::queryAddress()})
        query.append(reinterpret_cast<const char *>(frame.data()), qsizetype(frame.size()));
    query.append("\r\n");
    const std::vector<int> &list = bauds.empty() ? defaultBauds() : bauds;
    for (int baud : list) {
        if (!port.setBaudRate(baud))
            continue;
        port.clear();
        QByteArray got = readFor(port, kListenMs);
        Family f = classify(got, &res.address);
        // Asked twice when the line stayed silent: a query right after a rate change can be
        // lost (the first bytes after a UART changes speed), and the HiPNUC detection does the same.
        for (int attempt = 0; attempt < 2 && f == Family::Unknown && (attempt == 0 || got.isEmpty()); ++attempt) {
            port.write(query);
            port.waitForBytesWritten(200);
            got += readFor(port, kAnswerMs);
            f = classify(got, &res.address);
        }
        qCDebug(lcDetect) << baud << "baud:" << got.size() << "bytes," << familyName(f);
        if (f != Family::Unknown) {
            res.family = f;
            res.baud = baud;
            if (f != Family::Hec495)
                res.address = -1;
            return res;
        }
    }
    QStringList rates;
    for (int b : list)
        rates << QString::number(b);
    res.error = tr("neither a HiPNUC module nor an HEC495 answered on %1 at %2 baud: check the power, the wiring "
                   "and that no other program holds the port")
                    .arg(portName, rates.join(QLatin1Char('/')));
    return res;
}

} // namespace imudesk::device
