#pragma once
// The CAN firmware update (hipnuc-protocol-notes 4.5: CANopen SDO to object 0x1F51) as a state
// machine over a CanFrameLink. run() is blocking and belongs in a worker thread
// (CanFirmwareUpdater) or a test; cancel() may be called from any thread and takes effect
// between frames.
//
//   Checking             the image alone (and against FlashLayout if given): nothing is sent
//   Identifying          SDO read of 0x1018:3 (up to 3 tries) (the version the application reports; an abort means
//                        "application present, version unknown"); no answer → 0x1F51:06: a
//                        bootloader that answers means an earlier update was interrupted → finish it
//   EnteringBootloader   0x1F51:05 to the application (100 ms, a timeout is tolerated), 20 ms pause
//   ConfirmingBootloader 0x1F51:06 to the bootloader (100 ms); 05 + 06 up to 5 times, 50 ms apart
//   Downloading          segmented download to 0x1F51:01 with the size (8000 ms for the initiate
//                        reply: the bootloader erases), 7-byte segments (4000 ms each), the vendor's
//                        last-segment rule; a reply that does not echo the segment is refused
//   Verifying            SDO read of 0x1F56:1 (CiA 302 program software identification): equal to
//                        the CRC-32 of the bytes sent → "bootloader CRC"; different → failed; abort or
//                        no answer → not verified by the bootloader (the restart is the only check)
//   StartingApplication  0x1F51:09 (100 ms; a timeout is accepted, an abort is an error)
//   Confirming           the application answers again: boot-up/heartbeat or 0x1018:3
//   Done / Failed / Cancelled
// A failure or cancel after the download began leaves the module in its bootloader (the
// application was erased), where the next run finds it and finishes the update.
#include "io/can_frame_link.h"
#include "core/firmware/update_flow.h"
#include "model/device_identity.h"
#include "protocol/can/sdo_segmented_download.h"
#include "protocol/ihex/firmware_image.h"

#include <QCoreApplication>
#include <QString>

#include <atomic>
#include <functional>
#include <optional>

namespace imudesk::firmware {

class CanUpdateFlow {
    Q_DECLARE_TR_FUNCTIONS(CanUpdateFlow)

public:
    // The abort code sent when the user cancels a download: CiA 301 0x08000000 "general error"
    // (CiA 301 has no "aborted by user" code).
    static constexpr uint32_t kAbortCancelledByUser = 0x08000000;
    static constexpr uint16_t kObjUpdate = 0x1F51;
    static constexpr uint16_t kObjSoftwareId = 0x1F56;
    static constexpr uint16_t kObjIdentity = 0x1018;
    static constexpr uint8_t kSubRevision = 3;

    enum class State {
        Idle, Checking, Identifying, EnteringBootloader, ConfirmingBootloader, Downloading, Verifying,
        StartingApplication, Confirming, Done, Failed, Cancelled
    };
    static QString stateName(State s);

    struct Options {
        uint8_t node = 8;
        bool finishInterrupted = true;
        std::optional<UpdateFlow::FlashLayout> layout;
        protocol::can::canopen::SdoSegmentedDownload::LastSegment lastSegment =
            protocol::can::canopen::SdoSegmentedDownload::LastSegment::Hipnuc;
        int enterAttempts = 5;
        int replyTimeoutMs = 100;
        int eraseTimeoutMs = 8000;
        int segmentTimeoutMs = 4000;
        int identifyTimeoutMs = 300;
        int identifyAttempts = 3;        // a bus just opened may lose the first request
        int verifyTimeoutMs = 500;
        int appStartTimeoutMs = 3000;
    };
    struct Result {
        bool ok = false;
        State finalState = State::Idle;
        State failedIn = State::Idle;
        QString message;
        QString verifyMethod;            // "bootloader CRC" or "application restarted"
        bool resumed = false;            // the module was found in its bootloader
        bool applicationAnsweredBefore = false;
        std::optional<model::FirmwareVersion> before, after;
        uint32_t imageCrc = 0;
        std::optional<uint32_t> bootloaderCrc;
        double downloadSeconds = 0;
        double totalSeconds = 0;
        uint64_t bytesSent = 0;
    };
    struct Observer {
        std::function<void(State)> stateChanged;
        std::function<void(uint64_t done, uint64_t total, double bytesPerSecond, double secondsLeft)> progress;
        std::function<void(const QString &)> log;
    };

    CanUpdateFlow(CanFrameLink &link, Options options, Observer observer = {});

    // Offline check of an image (no device): empty, layout (the bootloader writes at appStart).
    static QString checkImage(const protocol::ihex::FirmwareImage &image, const std::optional<UpdateFlow::FlashLayout> &layout);

    Result run(const protocol::ihex::FirmwareImage &image);
    void cancel() { m_cancel = true; }
    State state() const { return m_state; }

private:
    enum class Answer { Reply, Abort, Timeout, LinkError };
    struct SdoAnswer {
        Answer answer = Answer::Timeout;
        uint32_t value = 0; // expedited data or abort code
    };
    SdoAnswer request(const protocol::can::CanFrame &frame, int timeoutMs, QString *error);
    SdoAnswer readVersion(int timeoutMs, std::optional<model::FirmwareVersion> *version, QString *error);
    bool enterBootloader(bool fromApplication, QString *error);
    bool download(const std::vector<uint8_t> &data, Result &r, QString *error, bool *cancelled);
    bool confirmApplication(Result &r, QString *error);
    void setState(State s);
    void log(const QString &line);
    Result finish(Result r, State state, const QString &message);
    void progressTick(uint64_t done, uint64_t total, int64_t startUs, bool force);

    CanFrameLink &m_link;
    Options m_options;
    Observer m_observer;
    std::atomic<bool> m_cancel{false};
    State m_state = State::Idle;
    int64_t m_lastProgressUs = 0;
    int64_t m_t0 = 0;
};

} // namespace imudesk::firmware
