// HiPNUC modules on a serial port, as the link opener sees them (serial_family.h): binary
// 5A A5 frames or an answer to LOG VERSION show one; DeviceSession is its session.
#include "device/device_session.h"
#include "device/hipnuc_family.h"
#include "links/link_opener.h"
#include "links/serial_family.h"
#include "protocol/hipnuc/ascii_command.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "sim/pty_simulator.h"

#include <QCoreApplication>

#include <algorithm>

namespace imudesk::device {

namespace {

namespace hp = protocol::hipnuc;

class HipnucRecogniser : public SerialRecogniser {
public:
    bool recognise(const QByteArray &held, qsizetype newFrom, int *) override
    {
        const auto *p = reinterpret_cast<const uint8_t *>(held.constData()) + newFrom;
        if (!m_frames.feed(p, size_t(held.size() - newFrom)).empty())
            return true;
        // A reply line ("OK", or the KEY=VALUE lines of LOG VERSION), looked for where the new
        // bytes may complete one.
        const qsizetype from = std::max<qsizetype>(0, newFrom - 5);
        return held.indexOf("\r\nOK\r\n", from) >= 0 || held.startsWith("OK\r\n") || held.indexOf("PNAME=", from) >= 0;
    }

private:
    hp::FrameDecoder m_frames;
};

class HipnucSerialKind : public SerialFamilyKind {
    Q_DECLARE_TR_FUNCTIONS(HipnucSerialKind)
public:
    QString id() const override { return QStringLiteral("hipnuc"); }
    QString displayName() const override { return tr("a HiPNUC module"); }
    std::vector<int> bauds() const override { return HipnucSerialFamily::detectionBauds(); }
    QByteArray query(int) const override { return QByteArray::fromStdString(hp::commands::logVersion().wire()); }
    std::unique_ptr<SerialRecogniser> recogniser() const override { return std::make_unique<HipnucRecogniser>(); }

    OpenedLink open(const LinkRequest &r, std::unique_ptr<io::Transport> transport) const override
    {
        auto s = std::make_unique<DeviceSession>(nullptr, std::move(transport));
        s->setAutoReconnect(r.autoReconnect);
        OpenedLink o;
        o.start = [p = s.get(), port = r.address, baud = r.baud] { p->open(port, baud); };
        o.link = std::move(s);
        return o;
    }

    bool startSimulator(LinkRequest &r, QString *error) const override
    {
        const auto *given = std::any_cast<sim::SimOptions>(&r.simulator);
        sim::SimOptions options = given ? *given : sim::SimOptions{};
        if (!given)
            options.motion = r.motion;
        return startOnPty(r, std::make_shared<sim::PtySimulator>(options),
                          tr("The simulated device could not start: %1"), error);
    }
};

} // namespace

const SerialFamilyKind &hipnucSerialKind()
{
    static const HipnucSerialKind kind;
    return kind;
}

} // namespace imudesk::device
