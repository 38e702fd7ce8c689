#pragma once
// Serves one simulated serial device (a HipnucSimulator, or any SimulatedSerialDevice such
// as the HEC495 compass) on a Linux pseudo-terminal, so that real serial code (QSerialPort,
// the CLI, the GUI) can open it like a USB serial adapter.
//
// The simulator runs in its own QThread: a QSocketNotifier reads the master side and
// a ~1 ms timer advances the simulated clock (steady clock, µs since start()) and
// writes what the module sends. Clients open devicePath() (the slave, /dev/pts/N). The
// thread asks for the same raised priority as a session's reading thread
// (io/reading_priority.h): it stands in for a device that does not share the host's CPU.
//
// UART model: on every read and write the line speed the client set on the slave is
// read (readLineSpeed on the master; termios2 for non-standard rates such as 256000).
// When it differs from the module's baud, bytes from the client are discarded and
// every byte the module sends is replaced by deterministic garbage (about
// clientBaud/moduleBaud bytes per byte sent), as a module heard at the wrong baud.
// While no client has the slave open, output is lost (nothing is buffered for the next
// client). A reader that stalls loses whole data frames once kMaxPendingBytes are
// waiting beyond what the pty itself holds (about 16 KiB on Linux 6.x: 4 KiB in the line
// discipline, the rest in its flip buffer); replies are kept (bounded by kHardLimitBytes).
// Together they hold what the kernel holds for a real serial port (a USB adapter or a UART):
// 640 KiB in the tty's flip buffer (TTYB_DEFAULT_MEM_LIMIT, Linux >= 3.x) and 4 KiB in the line
// discipline, about 7 s at 921600 baud. A pty alone holds 40 times less (pty.c limits its flip
// buffer to 8 KiB), which made a host that stopped the reader for 0.2 s lose frames that no real
// port would have lost.
//
// Unplugged cable (SimFaults::unplugAtS of a HiPNUC module's options): that many seconds after
// start() the simulator closes the master side, as when a USB serial adapter is pulled: the
// client's reads and writes fail (a hang-up, EIO), the slave goes away once the client closes
// it, and the device never comes back (stats().unplugged; stop() and start() plug in a new one).
#include "sim/hipnuc_simulator.h"
#include "sim/sim_clock.h"
#include "sim/simulated_serial_device.h"

#include <QCoreApplication>
#include <QString>

#include <cstdint>
#include <functional>
#include <memory>

QT_BEGIN_NAMESPACE
class QThread;
class QObject;
QT_END_NAMESPACE

namespace imudesk::sim {

class PtySimulator {
    Q_DECLARE_TR_FUNCTIONS(PtySimulator)

public:
    static constexpr size_t kMaxPendingBytes = 624 * 1024;
    static constexpr size_t kHardLimitBytes = kMaxPendingBytes + 64 * 1024;
    static constexpr int kTickMs = 1;
    // A HiPNUC session's line-idle time (HipnucFamily::kLineIdleMs): a pause inside a frame
    // this long makes it drop the frame (a HEC495 session's, 30 ms, drops on shorter ones).
    static constexpr int64_t kPauseInsideFrameUs = 120000;

    struct Stats {
        uint64_t bytesIn = 0;          // from the client, given to the module
        uint64_t bytesDiscarded = 0;   // from the client at the wrong speed
        uint64_t bytesOut = 0;         // written to the client
        uint64_t bytesGarbled = 0;     // module bytes replaced by garbage
        uint64_t bytesLost = 0;        // module bytes sent while no client was listening
        uint64_t chunksDropped = 0;    // frames dropped because the reader stalled
        // Frames the simulator's own thread left half-written in the pty for longer than
        // kPauseInsideFrameUs (the host did not run it): a real UART never pauses inside a frame,
        // and a session whose line-idle time is shorter drops that frame as unfinished.
        uint64_t framesPausedInside = 0;
        bool unplugged = false;        // the cable was pulled (SimFaults::unplugAtS)
    };

    // A HiPNUC module.
    explicit PtySimulator(SimOptions options = {});
    // Any simulated serial device (e.g. Hec495Simulator); it is used on the simulator thread.
    explicit PtySimulator(std::unique_ptr<SimulatedSerialDevice> device);
    ~PtySimulator();
    PtySimulator(const PtySimulator &) = delete;
    PtySimulator &operator=(const PtySimulator &) = delete;

    // The device's oscillator and the USB adapter's batching (sim_clock.h), set before start():
    // the device runs on clock.deviceUs(true time) (a HiPNUC module's motion stays in true
    // time), and what it sends reaches the pty as the adapter releases it.
    void setClock(ClockError clock);
    void setAdapter(AdapterLatency adapter) { m_adapter = adapter; }
    // A pulse source wired to SYNC_IN (v1.7.1 manual 2.2.1): a rising edge every 1/hz s, at
    // whole multiples of the period on the host's clock, so every simulator on this host that
    // has one sees the same edges (one source wired to several modules). A HiPNUC module then
    // sends a frame of each message set to ONMARK 1 at each edge. 0: none. Before start().
    void setSyncIn(double hz) { m_syncInHz = hz; }
    const ClockError &clock() const { return m_clock; }
    // The host time (clock::hostNowNs) of an instant of the device's own time, e.g. a HiPNUC
    // module's sample at system_time s: trueHostNs(startedAtUs() + s * 1000). 0 before start().
    int64_t trueHostNs(int64_t deviceUs) const;

    // Opens the pseudo-terminal and starts the simulator thread; blocks until ready.
    bool start(QString *error = nullptr);
    // Stops the thread and closes the master. Safe to call twice.
    void stop();
    bool isRunning() const;
    // The slave path (e.g. "/dev/pts/3"); empty before start().
    QString devicePath() const;
    // Runs fn on the simulator thread and waits for it (e.g. powerCycle, inspect state).
    // Only when the device is a HiPNUC module (otherwise fn is not called).
    void withDevice(const std::function<void(HipnucSimulator &)> &fn);
    // Any device.
    void withSerialDevice(const std::function<void(SimulatedSerialDevice &)> &fn);
    Stats stats() const;
    // Pulls the cable now (as SimFaults::unplugAtS does at its time): for a test that needs it
    // at a moment of its own choosing.
    void unplug();

    // Line speed (bit/s) of a tty or pty (master: the slave's settings); -1 on failure.
    static int readLineSpeed(int fd);

private:
    struct Engine;
    SimOptions m_options;
    ClockError m_clock;
    AdapterLatency m_adapter;
    double m_syncInHz = 0;
    std::unique_ptr<SimulatedSerialDevice> m_device; // until start() hands it to the engine
    bool m_customDevice = false; // a given device survives stop() (a HiPNUC one starts afresh)
    std::unique_ptr<Engine> m_engine;
    QThread *m_thread = nullptr;
    QObject *m_context = nullptr; // lives in m_thread
    QString m_path;
};

} // namespace imudesk::sim
