#pragma once
// The serial firmware update (KBOOT) as a state machine over a ByteLink. run() is blocking
// and belongs in a worker thread (FirmwareUpdater) or a test; cancel() may be called from
// any thread and takes effect between packets.
//
//   Checking          the image alone (and against FlashLayout if given): nothing is sent
//   Identifying       LOG VERSION at the application baud; no answer → ping: a bootloader that
//                     answers means an earlier update was interrupted → finish it (Options)
//   EnteringBootloader REBOOT BL, 50 ms
//   Pinging           up to 10 pings, 100 ms apart
//   ReadingProperties MaxPacketSize, FlashSizeInBytes (required), FlashSectorSize,
//                     FlashStartAddress, BootloaderVersion, CurrentVersion (optional);
//                     then the image is checked against them: nothing erased before this
//   Erasing           FlashEraseRegion over the image's sectors (start must be sector-aligned)
//   Writing           WriteMemory + data packets of min(MaxPacketSize, 512) rounded to 4 bytes
//   Verifying         ReadMemory of the written range, compared byte for byte ("read-back");
//                     a bootloader without ReadMemory fails the update as "not verified"
//   Resetting         Reset
//   Confirming        LOG VERSION at the application baud until the application answers; a
//                     module silent there for kConfirmAtUpdateBaudMs is looked for at the other
//                     rates of Options::otherBauds (it restarts at its *saved* rate, and the update
//                     may have run at a rate set but not saved), then at the update's rate again
//   Done / Failed / Cancelled
// A failure or cancel after erasing leaves the module in its bootloader (its application
// is invalid), where the next run finds it and finishes the update.
#include "io/byte_link.h"
#include "model/device_identity.h"
#include "protocol/ihex/firmware_image.h"

#include <QCoreApplication>
#include <QString>

#include <atomic>
#include <functional>
#include <optional>
#include <vector>

namespace imudesk::firmware {

class KbootClient;

class UpdateFlow {
    Q_DECLARE_TR_FUNCTIONS(UpdateFlow)

public:
    enum class State {
        Idle, Checking, Identifying, EnteringBootloader, Pinging, ReadingProperties, Erasing, Writing, Verifying,
        Resetting, Confirming, Done, Failed, Cancelled
    };
    static QString stateName(State s);

    // Where the application may go, when known before talking to the device.
    struct FlashLayout {
        uint32_t flashStart = 0;
        uint32_t flashSize = 0;
        uint32_t appStart = 0;
    };
    struct Options {
        int baud = 115200;
        bool finishInterrupted = true;   // continue when the module is already in its bootloader
        std::optional<FlashLayout> layout;
        int pingAttempts = 10;
        int maxPacketRetries = 3;
        int appStartTimeoutMs = 5000;    // the application must answer LOG VERSION after Reset
        int identifyTimeoutMs = 600;
        // Where the restarted application is looked for when it is silent at `baud` (the
        // module's serial rates); empty: only at `baud`.
        std::vector<int> otherBauds = {115200, 921600, 460800, 230400, 256000, 57600, 38400, 19200, 9600, 4800};
    };
    struct Progress {
        State state = State::Idle;
        uint64_t done = 0, total = 0;
        double bytesPerSecond = 0;
        double secondsLeft = -1;         // < 0: unknown
    };
    struct DeviceInfo {
        uint32_t maxPacketSize = 0, flashStart = 0, flashSize = 0, sectorSize = 0;
        std::optional<uint32_t> bootloaderVersion, currentVersion;
    };
    struct Result {
        bool ok = false;
        State finalState = State::Idle;
        State failedIn = State::Idle;
        QString message;
        QString verifyMethod;            // "read-back" when verified
        bool resumed = false;            // the module was found in its bootloader
        std::optional<model::DeviceIdentity> before, after;
        DeviceInfo device;
        double writeSeconds = 0;         // data phase only
        double totalSeconds = 0;
        uint64_t bytesWritten = 0;
        int afterBaud = 0;               // the rate the application answered at after the restart
    };
    struct Observer {
        std::function<void(State)> stateChanged;
        std::function<void(const Progress &)> progress;
        std::function<void(const QString &)> log;
    };

    UpdateFlow(ByteLink &link, Options options, Observer observer = {});

    // Offline check of an image (no device): empty, word alignment, layout.
    static QString checkImage(const protocol::ihex::FirmwareImage &image, const std::optional<FlashLayout> &layout);
    // The image against what the bootloader reported.
    static QString checkAgainstDevice(const protocol::ihex::FirmwareImage &image, const DeviceInfo &device,
                                      const std::optional<FlashLayout> &layout);

    Result run(const protocol::ihex::FirmwareImage &image);
    void cancel() { m_cancel = true; }
    State state() const { return m_state; }

private:
    void setState(State s);
    void log(const QString &line);
    std::optional<model::DeviceIdentity> queryVersion(int timeoutMs, QString *error);
    // Confirming: the application's answer after the restart, at the update's rate or another.
    std::optional<model::DeviceIdentity> awaitApplication(int *baud, QString *error);
    bool readProperties(KbootClient &kb, DeviceInfo &info, QString *error);
    Result finish(Result r, State state, const QString &message);
    bool progressTick(uint64_t done, uint64_t total, int64_t startUs);

    ByteLink &m_link;
    Options m_options;
    Observer m_observer;
    std::atomic<bool> m_cancel{false};
    State m_state = State::Idle;
    int64_t m_lastProgressUs = 0;
};

} // namespace imudesk::firmware
