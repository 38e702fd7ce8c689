#include "can_update_flow.h"

#include "protocol/can/canopen.h"
#include "protocol/can/sdo.h"

#include <QLoggingCategory>

#include <algorithm>

namespace imudesk::firmware {

namespace {

Q_LOGGING_CATEGORY(lcCanUpdate, "imudesk.core.firmware.can", QtInfoMsg)

using protocol::ihex::FirmwareImage;
using protocol::can::CanFrame;
namespace co = protocol::can::canopen;

constexpr uint8_t kSubDownload = 0x01;
constexpr uint8_t kSubEnter = 0x05;
constexpr uint8_t kSubConfirm = 0x06;
constexpr uint8_t kSubStart = 0x09;
constexpr int kEnterPauseMs = 20;  // notes 4.5: after 0x1F51:05
constexpr int kRetryPauseMs = 50;  // between the 05/06 attempts
constexpr int kConfirmPollMs = 200;

QString hex32(uint64_t v)
{
    return QStringLiteral("0x") + QString::number(qulonglong(v), 16).toUpper().rightJustified(8, QLatin1Char('0'));
}

QString versionText(const std::optional<model::FirmwareVersion> &v)
{
    return v ? QString::fromStdString(v->toString()) : CanUpdateFlow::tr("unknown");
}

std::optional<model::FirmwareVersion> versionFromRevision(uint32_t v)
{
    if (v == 0)
        return std::nullopt;
    return model::FirmwareVersion{int(v >> 16), int((v >> 8) & 0xFF), int(v & 0xFF)};
}

} // namespace

QString CanUpdateFlow::stateName(State s)
{
    switch (s) {
    case State::Idle: return tr("idle");
    case State::Checking: return tr("checking the image");
    case State::Identifying: return tr("identifying the module");
    case State::EnteringBootloader: return tr("entering the bootloader");
    case State::ConfirmingBootloader: return tr("confirming the bootloader");
    case State::Downloading: return tr("downloading");
    case State::Verifying: return tr("verifying");
    case State::StartingApplication: return tr("starting the application");
    case State::Confirming: return tr("confirming the new version");
    case State::Done: return tr("done");
    case State::Failed: return tr("failed");
    case State::Cancelled: return tr("cancelled");
    }
    return {};
}

CanUpdateFlow::CanUpdateFlow(CanFrameLink &link, Options options, Observer observer)
    : m_link(link), m_options(std::move(options)), m_observer(std::move(observer))
{
}

void CanUpdateFlow::setState(State s)
{
    m_state = s;
    qCDebug(lcCanUpdate) << "state" << stateName(s);
    if (m_observer.stateChanged)
        m_observer.stateChanged(s);
}

void CanUpdateFlow::log(const QString &line)
{
    qCInfo(lcCanUpdate).noquote() << line;
    if (m_observer.log)
        m_observer.log(line);
}

QString CanUpdateFlow::checkImage(const FirmwareImage &image, const std::optional<UpdateFlow::FlashLayout> &layout)
{
    if (image.empty())
        return tr("the image is empty");
    if (layout) {
        const uint64_t flashEnd = uint64_t(layout->flashStart) + layout->flashSize;
        if (image.startAddress != layout->appStart)
            return tr("the image starts at %1, but the CAN bootloader writes the application at %2 (addresses are "
                      "not transmitted); this is not an application image for this module")
                .arg(hex32(image.startAddress), hex32(layout->appStart));
        if (image.endAddress() > flashEnd)
            return tr("the image ends at %1, beyond the end of the flash at %2; it does not fit this module")
                .arg(hex32(image.endAddress()), hex32(flashEnd));
    }
    return {};
}

CanUpdateFlow::Result CanUpdateFlow::finish(Result r, State state, const QString &message)
{
    r.failedIn = state == State::Done ? State::Idle : m_state;
    r.ok = state == State::Done;
    r.finalState = state;
    r.message = message;
    r.totalSeconds = double(m_link.nowUs() - m_t0) / 1e6;
    setState(state);
    log(message);
    return r;
}

void CanUpdateFlow::progressTick(uint64_t done, uint64_t total, int64_t startUs, bool force)
{
    const int64_t now = m_link.nowUs();
    if (!m_observer.progress || (!force && now - m_lastProgressUs < 50000))
        return;
    m_lastProgressUs = now;
    const double secs = double(now - startUs) / 1e6;
    double rate = 0, left = -1;
    if (secs > 0 && done > 0) {
        rate = double(done) / secs;
        left = double(total - done) / rate;
    }
    m_observer.progress(done, total, rate, left);
}

CanUpdateFlow::SdoAnswer CanUpdateFlow::request(const CanFrame &frame, int timeoutMs, QString *error)
{
    SdoAnswer a;
    const auto req = co::parseSdo(frame);
    m_link.clearInput();
    if (!m_link.send(frame, error)) {
        a.answer = Answer::LinkError;
        return a;
    }
    const int64_t deadline = m_link.nowUs() + int64_t(timeoutMs) * 1000;
    std::vector<CanFrame> frames;
    while (m_link.nowUs() < deadline) {
        frames.clear();
        const int left = int(std::max<int64_t>(1, (deadline - m_link.nowUs() + 999) / 1000));
        if (!m_link.receive(frames, left, error)) {
            a.answer = Answer::LinkError;
            return a;
        }
        for (const CanFrame &f : frames) {
            const auto m = co::parseSdo(f);
            if (!m || !req || !co::sdoAnswers(*m, *req))
                continue;
            if (m->kind == co::SdoKind::Abort) {
                a.answer = Answer::Abort;
                a.value = m->value;
                return a;
            }
            const bool write = req->kind == co::SdoKind::DownloadExpedited || req->kind == co::SdoKind::DownloadSegmentedInit;
            if ((write && m->kind == co::SdoKind::DownloadReply) || (!write && m->kind == co::SdoKind::UploadExpedited)) {
                a.answer = Answer::Reply;
                a.value = m->value;
                return a;
            }
        }
    }
    a.answer = Answer::Timeout;
    return a;
}

CanUpdateFlow::SdoAnswer CanUpdateFlow::readVersion(int timeoutMs, std::optional<model::FirmwareVersion> *version,
                                                    QString *error)
{
    const SdoAnswer a = request(co::sdoRead(m_options.node, kObjIdentity, kSubRevision), timeoutMs, error);
    if (a.answer == Answer::Reply)
        *version = versionFromRevision(a.value);
    return a;
}

bool CanUpdateFlow::enterBootloader(bool fromApplication, QString *error)
{
    for (int attempt = 1; attempt <= std::max(1, m_options.enterAttempts); ++attempt) {
        if (m_cancel)
            return false;
        if (fromApplication) {
            setState(State::EnteringBootloader);
            const SdoAnswer a = request(co::sdoWrite(m_options.node, kObjUpdate, kSubEnter, 0), m_options.replyTimeoutMs, error);
            if (a.answer == Answer::LinkError)
                return false;
            if (a.answer == Answer::Abort) {
                *error = tr("the application refused to enter its bootloader (0x1F51:05): %1").arg(co::abortText(a.value));
                return false;
            }
            m_link.sleepMs(kEnterPauseMs);
        }
        setState(State::ConfirmingBootloader);
        const SdoAnswer c = request(co::sdoWrite(m_options.node, kObjUpdate, kSubConfirm, 0), m_options.replyTimeoutMs, error);
        if (c.answer == Answer::LinkError)
            return false;
        if (c.answer == Answer::Reply)
            return true;
        if (c.answer == Answer::Abort) {
            *error = tr("the bootloader refused the confirmation (0x1F51:06): %1").arg(co::abortText(c.value));
            return false;
        }
        log(tr("no bootloader confirmation yet (attempt %1 of %2)").arg(attempt).arg(m_options.enterAttempts));
        m_link.sleepMs(kRetryPauseMs);
    }
    *error = tr("the module did not confirm its bootloader (0x1F51:06) after %1 attempts; check the node ID and "
                "power-cycle the module")
                 .arg(m_options.enterAttempts);
    return false;
}

bool CanUpdateFlow::download(const std::vector<uint8_t> &data, Result &r, QString *error, bool *cancelled)
{
    co::SdoSegmentedDownload dl(m_options.node, kObjUpdate, kSubDownload, data, m_options.lastSegment);
    CanFrame out = dl.start();
    const int64_t d0 = m_link.nowUs();
    m_link.clearInput();
    progressTick(0, data.size(), d0, true);
    bool initiate = true;
    size_t segment = 0;
    auto abortTransfer = [&](uint32_t code) {
        QString ignored;
        m_link.send(co::sdoAbortFrame(m_options.node, kObjUpdate, kSubDownload, code, false), &ignored);
    };
    while (dl.status() == co::SdoSegmentedDownload::Status::Running) {
        if (m_cancel && !initiate) {
            abortTransfer(kAbortCancelledByUser);
            *cancelled = true;
            *error = tr("cancelled after %1 of %2 bytes").arg(dl.sent()).arg(data.size());
            return false;
        }
        if (!m_link.send(out, error))
            return false;
        const int timeoutMs = initiate ? m_options.eraseTimeoutMs : m_options.segmentTimeoutMs;
        const int64_t deadline = m_link.nowUs() + int64_t(timeoutMs) * 1000;
        bool answered = false;
        std::vector<CanFrame> frames;
        while (!answered && m_link.nowUs() < deadline) {
            frames.clear();
            const int left = int(std::max<int64_t>(1, (deadline - m_link.nowUs() + 999) / 1000));
            if (!m_link.receive(frames, left, error))
                return false;
            for (const CanFrame &f : frames) {
                if (!dl.onFrame(f))
                    continue;
                answered = true;
                if (!initiate && dl.status() != co::SdoSegmentedDownload::Status::Failed) {
                    // PY-NEW: the bootloader echoes bytes 1..7; a reply with other non-zero bytes is damaged.
                    const bool zeros = std::all_of(f.data.begin() + 1, f.data.begin() + 8, [](uint8_t b) { return b == 0; });
                    if (!zeros && !std::equal(f.data.begin() + 1, f.data.begin() + 8, out.data.begin() + 1)) {
                        abortTransfer(co::AbortGeneral);
                        *error = tr("the reply to segment %1 does not echo its data (%2); the reply is damaged")
                                     .arg(segment)
                                     .arg(f.dataText());
                        return false;
                    }
                }
                break;
            }
        }
        if (!answered) {
            abortTransfer(co::AbortTimeout);
            *error = initiate ? tr("the bootloader did not accept the download of %1 bytes within %2 ms (it erases "
                                   "first)")
                                    .arg(data.size())
                                    .arg(timeoutMs)
                              : tr("no reply to segment %1 (byte %2 of %3) within %4 ms")
                                    .arg(segment)
                                    .arg(dl.sent())
                                    .arg(data.size())
                                    .arg(timeoutMs);
            return false;
        }
        if (dl.status() == co::SdoSegmentedDownload::Status::Failed) {
            if (dl.abortCode() == co::AbortToggle)
                abortTransfer(co::AbortToggle); // our side ends the transfer too
            *error = initiate ? tr("the bootloader refused the download of %1 bytes: %2").arg(data.size()).arg(dl.error())
                              : tr("segment %1 (byte %2 of %3): %4").arg(segment).arg(dl.sent()).arg(data.size()).arg(dl.error());
            return false;
        }
        if (initiate)
            log(tr("the bootloader accepted %1 bytes (erase took %2 ms)").arg(data.size()).arg((m_link.nowUs() - d0) / 1000));
        initiate = false;
        ++segment;
        progressTick(dl.sent(), data.size(), d0, dl.status() == co::SdoSegmentedDownload::Status::Done);
        out = dl.next();
    }
    r.bytesSent = dl.sent();
    r.downloadSeconds = double(m_link.nowUs() - d0) / 1e6;
    return true;
}

bool CanUpdateFlow::confirmApplication(Result &r, QString *error)
{
    const int64_t until = m_link.nowUs() + int64_t(m_options.appStartTimeoutMs) * 1000;
    const uint32_t bootId = co::CobHeartbeat + m_options.node;
    bool alive = false;
    std::vector<CanFrame> frames;
    while (m_link.nowUs() < until) {
        frames.clear();
        if (!m_link.receive(frames, kConfirmPollMs, error))
            return false;
        for (const CanFrame &f : frames)
            alive = alive || (f.id == bootId && !f.extended && f.len >= 1);
        const SdoAnswer a = readVersion(m_options.identifyTimeoutMs, &r.after, error);
        if (a.answer == Answer::LinkError)
            return false;
        if (a.answer == Answer::Reply || a.answer == Answer::Abort || alive)
            return true;
    }
    *error = tr("the application did not answer within %1 s after the start (no boot-up, heartbeat or SDO reply); "
                "the image may not be a firmware for this module")
                 .arg(m_options.appStartTimeoutMs / 1000.0);
    return false;
}

CanUpdateFlow::Result CanUpdateFlow::run(const FirmwareImage &image)
{
    Result r;
    m_t0 = m_link.nowUs();
    setState(State::Checking);
    if (const QString e = checkImage(image, m_options.layout); !e.isEmpty())
        return finish(r, State::Failed, tr("refused before contacting the module: %1").arg(e));
    if (m_options.node < 1 || m_options.node > 127)
        return finish(r, State::Failed, tr("refused: node %1 is not a CANopen node ID (1..127)").arg(m_options.node));
    r.imageCrc = image.crc32();
    log(tr("image: %1 bytes at %2, CRC-32 %3").arg(image.size()).arg(hex32(image.startAddress), hex32(r.imageCrc)));

    QString e;
    if (!m_link.isOpen() && !m_link.open(&e))
        return finish(r, State::Failed, e);

    setState(State::Identifying);
    SdoAnswer id;
    for (int attempt = 0; attempt < std::max(1, m_options.identifyAttempts) && id.answer == Answer::Timeout; ++attempt) {
        id = readVersion(m_options.identifyTimeoutMs, &r.before, &e);
        if (id.answer == Answer::LinkError)
            return finish(r, State::Failed, e);
    }
    if (id.answer != Answer::Timeout) {
        r.applicationAnsweredBefore = true;
        log(tr("node %1: application answers, firmware %2").arg(m_options.node).arg(versionText(r.before)));
    } else {
        const SdoAnswer boot = request(co::sdoWrite(m_options.node, kObjUpdate, kSubConfirm, 0), m_options.replyTimeoutMs, &e);
        if (boot.answer == Answer::LinkError)
            return finish(r, State::Failed, e);
        if (boot.answer != Answer::Reply)
            return finish(r, State::Failed, tr("nothing answered on node %1: neither the application (SDO 0x1018:3) nor "
                                               "the bootloader (0x1F51:06). Check the node ID, the bit rate, the "
                                               "termination and the power")
                                                .arg(m_options.node));
        r.resumed = true;
        if (!m_options.finishInterrupted)
            return finish(r, State::Failed, tr("the module is already in its bootloader (an earlier update was "
                                               "interrupted); run the update again and allow finishing it"));
        log(tr("the module is already in its bootloader: an earlier update was interrupted; finishing it"));
    }
    if (m_cancel)
        return finish(r, State::Cancelled, tr("cancelled; the module was not changed"));

    if (!r.resumed && !enterBootloader(true, &e)) {
        if (m_cancel)
            return finish(r, State::Cancelled, tr("cancelled before the download; the module was not changed (if it "
                                                  "is in its bootloader, run the update again)"));
        return finish(r, State::Failed, e);
    }
    log(tr("bootloader confirmed on node %1").arg(m_options.node));
    if (m_cancel) {
        // Nothing erased yet: give the module its application back (unless it had none).
        QString back;
        if (!r.resumed)
            request(co::sdoWrite(m_options.node, kObjUpdate, kSubStart, 0), m_options.replyTimeoutMs, &back);
        return finish(r, State::Cancelled, r.resumed ? tr("cancelled before the download; the module stays in its "
                                                          "bootloader; run the update again to finish it")
                                                     : tr("cancelled before the download; the application was "
                                                          "restarted unchanged"));
    }

    setState(State::Downloading);
    bool cancelled = false;
    if (!download(image.data, r, &e, &cancelled)) {
        if (cancelled)
            return finish(r, State::Cancelled, tr("%1. The module stays in its bootloader without a valid "
                                                  "application; run the update again to finish it")
                                                   .arg(e));
        return finish(r, State::Failed, tr("the download failed: %1. The module stays in its bootloader; run the "
                                           "update again")
                                            .arg(e));
    }
    log(tr("%1 bytes sent in %2 s (%3 bytes/s)")
            .arg(r.bytesSent)
            .arg(r.downloadSeconds, 0, 'f', 2)
            .arg(r.downloadSeconds > 0 ? double(r.bytesSent) / r.downloadSeconds : 0, 0, 'f', 0));

    setState(State::Verifying);
    const SdoAnswer crc = request(co::sdoRead(m_options.node, kObjSoftwareId, 1), m_options.verifyTimeoutMs, &e);
    if (crc.answer == Answer::LinkError)
        return finish(r, State::Failed, e);
    if (crc.answer == Answer::Reply) {
        r.bootloaderCrc = crc.value;
        if (crc.value != r.imageCrc)
            return finish(r, State::Failed, tr("verification failed: the bootloader reports CRC-32 %1 for the written "
                                               "application, the image has %2. The application was not started; run "
                                               "the update again")
                                                .arg(hex32(crc.value), hex32(r.imageCrc)));
        r.verifyMethod = QStringLiteral("bootloader CRC");
        log(tr("verified: bootloader CRC %1 equals the image's").arg(hex32(crc.value)));
    } else {
        r.verifyMethod = QStringLiteral("application restarted");
        log(tr("the bootloader offers no CRC (0x1F56:1 %1); the restart of the application is the only check")
                .arg(crc.answer == Answer::Abort ? co::abortText(crc.value) : tr("not answered")));
    }

    setState(State::StartingApplication);
    const SdoAnswer start = request(co::sdoWrite(m_options.node, kObjUpdate, kSubStart, 0), m_options.replyTimeoutMs, &e);
    if (start.answer == Answer::LinkError)
        return finish(r, State::Failed, e);
    if (start.answer == Answer::Abort)
        return finish(r, State::Failed, tr("the bootloader refused to start the application (0x1F51:09): %1. Run the "
                                           "update again")
                                            .arg(co::abortText(start.value)));

    setState(State::Confirming);
    if (!confirmApplication(r, &e))
        return finish(r, State::Failed, tr("the image was sent but %1").arg(e));
    if (r.bootloaderCrc)
        return finish(r, State::Done, tr("updated: firmware %1 → %2, %3 bytes, verified: bootloader CRC %4")
                                          .arg(versionText(r.before), versionText(r.after))
                                          .arg(r.bytesSent)
                                          .arg(hex32(*r.bootloaderCrc)));
    return finish(r, State::Done, tr("updated: %1 bytes sent; not verified by the bootloader; application restarted "
                                     "with version %2")
                                      .arg(r.bytesSent)
                                      .arg(versionText(r.after)));
}

} // namespace imudesk::firmware
