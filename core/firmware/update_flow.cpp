#include "update_flow.h"
#include "protocol/hipnuc/ascii_command.h"

#include "core/firmware/kboot_client.h"
#include "protocol/hipnuc/ascii_reply.h"
#include "protocol/kboot/status_code.h"
#include "protocol/stream/stream_demux.h"

#include <QLoggingCategory>

#include <algorithm>
#include <cctype>
#include <string_view>

namespace imudesk::firmware {

namespace {

Q_LOGGING_CATEGORY(lcUpdate, "imudesk.core.firmware", QtInfoMsg)

using protocol::ihex::FirmwareImage;
using namespace protocol::kboot;

constexpr size_t kMaxDataPacket = 512; // notes 3.3 step 8: min(MaxPacketSize, 512)
constexpr int kRebootBlPauseMs = 50;
constexpr int kAfterPingPauseMs = 300;
constexpr int64_t kQuietMs = 30;
// Before LOG VERSION: listened to for at most this long, for a frame boundary (see queryVersion).
constexpr int64_t kListenBeforeQueryMs = 150;
// A module left in its bootloader by an interrupted update: pings 100 ms apart (their answers
// count however late they come while the pings last).
constexpr int kResumePingAttempts = 5;
// Confirming: how long the restarted application is waited for at the update's rate before the
// other rates are tried.
constexpr int kConfirmAtUpdateBaudMs = 1500;

QString hex32(uint64_t v)
{
    return QStringLiteral("0x") + QString::number(qulonglong(v), 16).toUpper().rightJustified(8, QLatin1Char('0'));
}

QString versionText(const std::optional<model::FirmwareVersion> &v)
{
    return v ? QString::fromStdString(v->toString()) : UpdateFlow::tr("unknown");
}

} // namespace

QString UpdateFlow::stateName(State s)
{
    switch (s) {
    case State::Idle: return tr("idle");
    case State::Checking: return tr("checking the image");
    case State::Identifying: return tr("identifying the module");
    case State::EnteringBootloader: return tr("entering the bootloader");
    case State::Pinging: return tr("contacting the bootloader");
    case State::ReadingProperties: return tr("reading the bootloader's properties");
    case State::Erasing: return tr("erasing");
    case State::Writing: return tr("writing");
    case State::Verifying: return tr("verifying");
    case State::Resetting: return tr("restarting the module");
    case State::Confirming: return tr("confirming the new version");
    case State::Done: return tr("done");
    case State::Failed: return tr("failed");
    case State::Cancelled: return tr("cancelled");
    }
    return {};
}

UpdateFlow::UpdateFlow(ByteLink &link, Options options, Observer observer)
    : m_link(link), m_options(std::move(options)), m_observer(std::move(observer))
{
}

void UpdateFlow::setState(State s)
{
    m_state = s;
    qCDebug(lcUpdate) << "state" << stateName(s);
    if (m_observer.stateChanged)
        m_observer.stateChanged(s);
}

void UpdateFlow::log(const QString &line)
{
    qCInfo(lcUpdate).noquote() << line;
    if (m_observer.log)
        m_observer.log(line);
}

QString UpdateFlow::checkImage(const FirmwareImage &image, const std::optional<FlashLayout> &layout)
{
    if (image.empty())
        return tr("the image is empty");
    if (image.startAddress % 4 != 0)
        return tr("the image starts at %1, which is not a multiple of 4; the bootloader writes whole words")
            .arg(hex32(image.startAddress));
    if (layout) {
        const uint64_t flashEnd = uint64_t(layout->flashStart) + layout->flashSize;
        if (image.startAddress < layout->appStart)
            return tr("the image starts at %1, below the application area at %2 (that is the bootloader); this is not "
                      "an application image for this module")
                .arg(hex32(image.startAddress), hex32(layout->appStart));
        if (image.endAddress() > flashEnd)
            return tr("the image ends at %1, beyond the end of the flash at %2; it does not fit this module")
                .arg(hex32(image.endAddress()), hex32(flashEnd));
    }
    return {};
}

QString UpdateFlow::checkAgainstDevice(const FirmwareImage &image, const DeviceInfo &d,
                                       const std::optional<FlashLayout> &layout)
{
    const uint64_t flashEnd = uint64_t(d.flashStart) + d.flashSize;
    if (image.startAddress < d.flashStart || image.endAddress() > flashEnd)
        return tr("the image (%1..%2) is outside the module's flash (%3..%4, %5 bytes reported by the bootloader)")
            .arg(hex32(image.startAddress), hex32(image.endAddress()), hex32(d.flashStart), hex32(flashEnd))
            .arg(d.flashSize);
    if (image.size() > d.flashSize)
        return tr("the image has %1 bytes, the module's flash only %2").arg(image.size()).arg(d.flashSize);
    if (d.sectorSize > 0 && (image.startAddress - d.flashStart) % d.sectorSize != 0)
        return tr("the image starts at %1, which is not on a flash sector boundary (sectors of %2 bytes); the erase "
                  "would destroy the bytes before it")
            .arg(hex32(image.startAddress))
            .arg(d.sectorSize);
    if (layout && image.startAddress < layout->appStart)
        return tr("the image starts at %1, below the application area at %2").arg(hex32(image.startAddress),
                                                                                   hex32(layout->appStart));
    return {};
}

UpdateFlow::Result UpdateFlow::finish(Result r, State state, const QString &message)
{
    r.failedIn = state == State::Done ? State::Idle : m_state;
    r.ok = state == State::Done;
    r.finalState = state;
    r.message = message;
    setState(state);
    log(message);
    return r;
}

bool UpdateFlow::progressTick(uint64_t done, uint64_t total, int64_t startUs)
{
    const int64_t now = m_link.nowUs();
    if (m_observer.progress && (done == total || now - m_lastProgressUs >= 50000 || done == 0)) {
        m_lastProgressUs = now;
        Progress p;
        p.state = m_state;
        p.done = done;
        p.total = total;
        const double secs = double(now - startUs) / 1e6;
        if (secs > 0 && done > 0) {
            p.bytesPerSecond = double(done) / secs;
            p.secondsLeft = double(total - done) / p.bytesPerSecond;
        }
        m_observer.progress(p);
    }
    return !m_cancel;
}

std::optional<model::DeviceIdentity> UpdateFlow::queryVersion(int timeoutMs, QString *error)
{
    using protocol::hipnuc::ReplyCollector;
    m_link.clearInput();
    protocol::StreamDemux demux;
    std::vector<uint8_t> buf;
    std::vector<protocol::StreamEvent> events;
    // Listen before asking, as the session does: a module that streams is joined mid-frame,
    // and that frame's tail (bytes that may look like text) would be glued to the reply's first
    // line. The demux's text quarantine ends at the first CRC-valid frame, or here when the
    // line falls quiet; a line that stays busy with neither is asked all the same.
    const int64_t listenUntil = m_link.nowUs() + kListenBeforeQueryMs * 1000;
    while (demux.quarantined() && m_link.nowUs() < listenUntil) {
        buf.clear();
        if (!m_link.read(buf, int(kQuietMs), error))
            return std::nullopt;
        events.clear();
        if (buf.empty()) {
            demux.flushPending(events); // quiet: no frame is under way
            break;
        }
        demux.feed(buf.data(), buf.size(), events);
    }
    demux.endQuarantine();
    const std::string query = protocol::hipnuc::commands::logVersion().wire();
    if (!m_link.write(std::vector<uint8_t>(query.begin(), query.end()), error))
        return std::nullopt;
    ReplyCollector reply("LOG VERSION");
    const int64_t deadline = m_link.nowUs() + int64_t(timeoutMs) * 1000;
    while (m_link.nowUs() < deadline) {
        buf.clear();
        const int64_t left = std::max<int64_t>(1, (deadline - m_link.nowUs()) / 1000);
        if (!m_link.read(buf, int(std::min<int64_t>(left, kQuietMs)), error))
            return std::nullopt;
        events.clear();
        if (buf.empty())
            demux.flushPending(events); // a quiet line: an unfinished frame candidate will not complete
        else
            demux.feed(buf.data(), buf.size(), events);
        for (const auto &e : events) {
            if (e.kind != protocol::StreamEvent::Kind::Line)
                continue;
            // The tail of a binary frame cut by our clearInput() may stick to the first line:
            // reply lines start with a letter or digit.
            std::string_view line(e.text);
            while (!line.empty() && !std::isalnum(uint8_t(line.front())))
                line.remove_prefix(1);
            if (!reply.addLine(line))
                continue;
            const auto r = reply.take();
            if (!r.ok())
                return std::nullopt;
            const auto id = model::DeviceIdentity::fromKeyValues(r.values);
            if (id.usable())
                return id;
            return std::nullopt;
        }
    }
    return std::nullopt;
}

bool UpdateFlow::readProperties(KbootClient &kb, DeviceInfo &info, QString *error)
{
    QString e;
    const auto packet = kb.getProperty(PropertyTag::MaxPacketSize, &e);
    if (!packet) {
        *error = tr("reading the maximum packet size failed: %1").arg(e);
        return false;
    }
    const auto flash = kb.getProperty(PropertyTag::FlashSizeInBytes, &e);
    if (!flash) {
        *error = tr("reading the flash size failed: %1").arg(e);
        return false;
    }
    info.maxPacketSize = *packet;
    info.flashSize = *flash;
    // Optional ones: an older bootloader may not know them (kStatus_UnknownProperty).
    info.sectorSize = kb.getProperty(PropertyTag::FlashSectorSize, &e).value_or(0);
    info.flashStart = kb.getProperty(PropertyTag::FlashStartAddress, &e).value_or(0);
    info.bootloaderVersion = kb.getProperty(PropertyTag::BootloaderVersion, &e);
    info.currentVersion = kb.getProperty(PropertyTag::CurrentVersion, &e);
    if (info.maxPacketSize < 4) {
        *error = tr("the bootloader reports a maximum packet size of %1 bytes; it cannot take data").arg(info.maxPacketSize);
        return false;
    }
    if (info.flashSize == 0) {
        *error = tr("the bootloader reports no flash");
        return false;
    }
    const uint32_t cv = info.currentVersion.value_or(0);
    log(tr("bootloader: max packet %1 bytes, flash %2 bytes from %3, sectors of %4 bytes, bootloader version %5, "
           "KBOOT %6%7.%8.%9")
            .arg(info.maxPacketSize)
            .arg(info.flashSize)
            .arg(hex32(info.flashStart))
            .arg(info.sectorSize)
            .arg(info.bootloaderVersion ? QString::number(*info.bootloaderVersion) : tr("unknown"))
            .arg(QChar(char(cv >> 24 ? cv >> 24 : '?')))
            .arg((cv >> 16) & 0xFF)
            .arg((cv >> 8) & 0xFF)
            .arg(cv & 0xFF));
    return true;
}

UpdateFlow::Result UpdateFlow::run(const FirmwareImage &image)
{
    Result r;
    const int64_t t0 = m_link.nowUs();
    setState(State::Checking);
    if (const QString e = checkImage(image, m_options.layout); !e.isEmpty())
        return finish(r, State::Failed, tr("refused before contacting the module: %1").arg(e));
    std::vector<uint8_t> data = image.data;
    while (data.size() % 4 != 0)
        data.push_back(0xFF); // erased flash value: the word's tail stays as erased
    log(tr("image: %1 bytes at %2, CRC-32 %3").arg(image.size()).arg(hex32(image.startAddress),
                                                                     hex32(image.crc32())));

    QString e;
    if (!m_link.isOpen() && !m_link.open(m_options.baud, &e))
        return finish(r, State::Failed, e);

    KbootClient::Timeouts timeouts;
    timeouts.maxRetries = m_options.maxPacketRetries;
    KbootClient kb(m_link, timeouts);
    PingResponse ping;

    setState(State::Identifying);
    r.before = queryVersion(m_options.identifyTimeoutMs, &e);
    if (!e.isEmpty())
        return finish(r, State::Failed, e);
    if (r.before) {
        log(tr("module %1, firmware %2, bootloader %3")
                .arg(QString::fromStdString(r.before->productName), versionText(r.before->firmware),
                     versionText(r.before->bootloader)));
    } else if (kb.ping(kResumePingAttempts, &ping, &e)) {
        r.resumed = true;
        if (!m_options.finishInterrupted)
            return finish(r, State::Failed,
                          tr("the module is already in its bootloader (an earlier update was interrupted); run the "
                             "update again and allow finishing it"));
        log(tr("the module is already in its bootloader: an earlier update was interrupted; finishing it"));
    } else {
        if (!m_link.isOpen())
            return finish(r, State::Failed, e);
        return finish(r, State::Failed,
                      tr("nothing answered at %1 baud: neither the application (LOG VERSION) nor the bootloader "
                         "(ping). Check the port, the baud rate and the power")
                          .arg(m_options.baud));
    }

    if (!r.resumed) {
        if (m_cancel)
            return finish(r, State::Cancelled, tr("cancelled; the module was not changed"));
        setState(State::EnteringBootloader);
        const std::string cmd = protocol::hipnuc::commands::rebootBootloader().wire();
        if (!m_link.write(std::vector<uint8_t>(cmd.begin(), cmd.end()), &e))
            return finish(r, State::Failed, e);
        m_link.sleepMs(kRebootBlPauseMs);
        setState(State::Pinging);
        if (!kb.ping(m_options.pingAttempts, &ping, &e))
            return finish(r, State::Failed, tr("the module did not enter its bootloader: %1").arg(e));
        m_link.sleepMs(kAfterPingPauseMs);
    }
    log(tr("bootloader answers: protocol %1%2.%3.%4")
            .arg(QChar(char(ping.name)))
            .arg(ping.major)
            .arg(ping.minor)
            .arg(ping.bugfix));

    setState(State::ReadingProperties);
    if (!readProperties(kb, r.device, &e))
        return finish(r, State::Failed, e);
    if (const QString bad = checkAgainstDevice(image, r.device, m_options.layout); !bad.isEmpty()) {
        QString back;
        // Nothing was erased: give the module its application back (unless we found it in the bootloader).
        if (!r.resumed && !kb.reset(&back))
            log(tr("could not restart the module: %1").arg(back));
        return finish(r, State::Failed, tr("refused before erasing: %1").arg(bad));
    }
    if (m_cancel)
        return finish(r, State::Cancelled, tr("cancelled before erasing; the module was not changed"));

    setState(State::Erasing);
    const uint32_t sector = std::max<uint32_t>(r.device.sectorSize, 1);
    const uint32_t eraseLen = uint32_t((uint64_t(data.size()) + sector - 1) / sector * sector);
    const int eraseTimeout = timeouts.eraseMs + int(eraseLen / sector) * 50;
    log(tr("erasing %1 bytes at %2").arg(eraseLen).arg(hex32(image.startAddress)));
    const bool erased = kb.flashEraseRegion(image.startAddress, eraseLen, eraseTimeout, &e);
    if (!erased && kb.lastStatus() != kStatusSuccess) {
        // The bootloader refused the region: nothing was erased, the application is intact.
        QString back;
        if (!r.resumed && !kb.reset(&back))
            log(tr("could not restart the module: %1").arg(back));
        return finish(r, State::Failed, tr("refused before erasing: %1; the module was not changed").arg(e));
    }
    if (!erased)
        return finish(r, State::Failed, tr("erasing failed: %1. The module stays in its bootloader; run the update "
                                           "again")
                                            .arg(e));

    setState(State::Writing);
    const size_t packet = std::min<size_t>(r.device.maxPacketSize, kMaxDataPacket) & ~size_t(3);
    const int64_t w0 = m_link.nowUs();
    progressTick(0, data.size(), w0);
    const bool written = kb.writeMemory(image.startAddress, data.data(), data.size(), packet,
                                        [&](uint64_t done) { return progressTick(done, data.size(), w0); }, &e);
    r.writeSeconds = double(m_link.nowUs() - w0) / 1e6;
    if (!written) {
        if (kb.cancelled())
            return finish(r, State::Cancelled,
                          tr("cancelled while writing (%1). The module stays in its bootloader without a valid "
                             "application; run the update again to finish it")
                              .arg(e));
        return finish(r, State::Failed, tr("writing failed: %1. The module stays in its bootloader; run the update "
                                           "again")
                                            .arg(e));
    }
    r.bytesWritten = data.size();
    log(tr("%1 bytes written in %2 s (%3 bytes/s, %4 NAK, %5 packets resent)")
            .arg(data.size())
            .arg(r.writeSeconds, 0, 'f', 2)
            .arg(r.writeSeconds > 0 ? double(data.size()) / r.writeSeconds : 0, 0, 'f', 0)
            .arg(kb.counters().naks)
            .arg(kb.counters().resent));

    setState(State::Verifying);
    std::vector<uint8_t> back;
    const int64_t v0 = m_link.nowUs();
    if (!kb.readMemory(image.startAddress, data.size(), back,
                       [&](uint64_t done) { return progressTick(done, data.size(), v0); }, &e)) {
        if (kb.cancelled())
            return finish(r, State::Cancelled, tr("cancelled while verifying; the module stays in its bootloader; run "
                                                  "the update again"));
        if (kb.lastStatus() == kStatusUnknownCommand || kb.lastStatus() == kStatusUnsupportedCommand)
            return finish(r, State::Failed, tr("the image was written but cannot be verified: the bootloader does not "
                                               "offer ReadMemory (%1). The module was not restarted")
                                                .arg(KbootStatus::message(kb.lastStatus())));
        return finish(r, State::Failed, tr("verifying failed: %1. Run the update again").arg(e));
    }
    const auto mismatch = std::mismatch(data.begin(), data.end(), back.begin());
    if (mismatch.first != data.end()) {
        const size_t at = size_t(mismatch.first - data.begin());
        return finish(r, State::Failed, tr("verification failed at %1: wrote %2, read %3. Run the update again")
                                            .arg(hex32(image.startAddress + at))
                                            .arg(*mismatch.first, 2, 16, QLatin1Char('0'))
                                            .arg(*mismatch.second, 2, 16, QLatin1Char('0')));
    }
    r.verifyMethod = QStringLiteral("read-back");
    log(tr("verified: %1 bytes read back and compared").arg(back.size()));

    setState(State::Resetting);
    if (!kb.reset(&e))
        return finish(r, State::Failed, tr("the image is written and verified, but the restart failed: %1. "
                                           "Power-cycle the module")
                                            .arg(e));
    setState(State::Confirming);
    e.clear();
    r.after = awaitApplication(&r.afterBaud, &e);
    r.totalSeconds = double(m_link.nowUs() - t0) / 1e6;
    if (!e.isEmpty())
        return finish(r, State::Failed, e);
    if (!r.after)
        return finish(r, State::Failed,
                      m_options.otherBauds.empty()
                          ? tr("the image is written and verified, but the application did not answer LOG VERSION "
                               "within %1 s after the restart; the image may not be a firmware for this module")
                                .arg(m_options.appStartTimeoutMs / 1000.0)
                          : tr("the image is written and verified, but the application did not answer LOG VERSION "
                               "at %1 baud within %2 s after the restart, nor at any other rate; the image may not "
                               "be a firmware for this module")
                                .arg(m_options.baud)
                                .arg(m_options.appStartTimeoutMs / 1000.0));
    QString done = tr("updated: firmware %1 → %2, %3 bytes verified by read-back")
                       .arg(r.before ? versionText(r.before->firmware) : tr("unknown"), versionText(r.after->firmware))
                       .arg(r.bytesWritten);
    if (r.afterBaud != m_options.baud)
        done += tr(". The module restarted at %1 baud, the rate saved in it: the update ran at %2 baud, a rate that "
                   "was set but not saved. It is connected again at %1 baud")
                    .arg(r.afterBaud)
                    .arg(m_options.baud);
    return finish(r, State::Done, done);
}

std::optional<model::DeviceIdentity> UpdateFlow::awaitApplication(int *baud, QString *error)
{
    const auto attempt = [&](int at) -> std::optional<model::DeviceIdentity> {
        auto id = queryVersion(m_options.identifyTimeoutMs, error);
        if (id)
            *baud = at;
        return id;
    };
    const int64_t t0 = m_link.nowUs();
    const int64_t until = t0 + int64_t(m_options.appStartTimeoutMs) * 1000;
    const int64_t lookElsewhere = t0 + int64_t(std::min(m_options.appStartTimeoutMs, kConfirmAtUpdateBaudMs)) * 1000;
    bool lookedElsewhere = false;
    while (m_link.nowUs() < until || !lookedElsewhere) {
        if (!lookedElsewhere && m_link.nowUs() >= lookElsewhere) {
            lookedElsewhere = true;
            for (int other : m_options.otherBauds) {
                if (other == m_options.baud)
                    continue;
                m_link.close();
                if (!m_link.open(other, error))
                    return std::nullopt;
                log(tr("no answer at %1 baud: looking for the application at %2 baud").arg(m_options.baud).arg(other));
                if (auto id = attempt(other))
                    return id;
                if (!error->isEmpty())
                    return std::nullopt;
            }
            if (!m_options.otherBauds.empty()) {
                m_link.close();
                if (!m_link.open(m_options.baud, error))
                    return std::nullopt;
            }
            continue;
        }
        m_link.sleepMs(100);
        if (auto id = attempt(m_options.baud))
            return id;
        if (!error->isEmpty())
            return std::nullopt;
    }
    return std::nullopt;
}

} // namespace imudesk::firmware
