// The Witlink HEC495 compass on a serial port, as the link opener sees it (serial_family.h):
// its 0x77 frames (auto-output, or the answer to "read all" / "query address") show one;
// Hec495Session is its session.
#include "device/hec495_family.h"
#include "device/hec495_session.h"
#include "links/link_opener.h"
#include "links/serial_family.h"
#include "protocol/witlink/commands.h"
#include "protocol/witlink/frame_decoder.h"
#include "protocol/witlink/reply.h"
#include "sim/hec495_simulator.h"
#include "sim/pty_simulator.h"

#include <QCoreApplication>

namespace imudesk::device {

namespace {

namespace wl = protocol::witlink;

class Hec495Recogniser : public SerialRecogniser {
public:
    bool recognise(const QByteArray &held, qsizetype newFrom, int *address) override
    {
        const auto *p = reinterpret_cast<const uint8_t *>(held.constData()) + newFrom;
        for (const auto &f : m_frames.feed(p, size_t(held.size() - newFrom))) {
            const wl::Reply r = wl::decodeReply(f);
            if (!r.ok())
                continue;
            if (r.kind == wl::Reply::Kind::AllData || r.kind == wl::Reply::Kind::Angles
                || r.kind == wl::Reply::Kind::Address) {
                *address = r.kind == wl::Reply::Kind::Address ? r.deviceAddress : r.address;
                return true;
            }
        }
        return false;
    }

private:
    wl::FrameDecoder m_frames;
};

class Hec495SerialKind : public SerialFamilyKind {
    Q_DECLARE_TR_FUNCTIONS(Hec495SerialKind)
public:
    QString id() const override { return QStringLiteral("hec495"); }
    QString displayName() const override { return tr("an HEC495 compass"); }
    std::vector<int> bauds() const override { return Hec495Family::detectionBauds(); }

    // "Read all" to the given address and "query address" (to 00, which every HEC495 answers,
    // manual 2.17), then "\r\n" so that a line-based device drops the binary as an unknown line.
    QByteArray query(int address) const override
    {
        QByteArray q;
        for (const auto &frame : {wl::commands::readAll(uint8_t(address)), wl::commands::queryAddress()})
            q.append(reinterpret_cast<const char *>(frame.data()), qsizetype(frame.size()));
        q.append("\r\n");
        return q;
    }

    std::unique_ptr<SerialRecogniser> recogniser() const override { return std::make_unique<Hec495Recogniser>(); }

    OpenedLink open(const LinkRequest &r, std::unique_ptr<io::Transport> transport) const override
    {
        auto s = std::make_unique<Hec495Session>(nullptr, std::move(transport));
        s->setAutoReconnect(r.autoReconnect);
        OpenedLink o;
        o.start = [p = s.get(), port = r.address, baud = r.baud, address = r.deviceAddress] {
            p->open(port, baud, address);
        };
        o.link = std::move(s);
        return o;
    }

    // A simulated compass streaming at 50 Hz.
    bool startSimulator(LinkRequest &r, QString *error) const override
    {
        const auto *given = std::any_cast<sim::Hec495Options>(&r.simulator);
        sim::Hec495Options options = given ? *given : sim::Hec495Options{};
        if (!given) {
            options.motion = r.motion;
            options.rateHz = 50;
        }
        r.baud = options.baud;
        r.deviceAddress = options.address;
        return startOnPty(r, std::make_shared<sim::PtySimulator>(std::make_unique<sim::Hec495Simulator>(options)),
                          tr("The simulated compass could not start: %1"), error);
    }
};

} // namespace

const SerialFamilyKind &hec495SerialKind()
{
    static const Hec495SerialKind kind;
    return kind;
}

} // namespace imudesk::device
