#pragma once
// Finding the rate a serial device talks at. For each rate of a list in turn: tune the link
// to it, listen a while (a device that streams is recognised before it is asked anything),
// then let the family probe; the family's answer ends the scan (found, or stopped) or moves
// it to the next rate. When the list runs out nobody answered.
//
// The two serial families use it for their detection (HipnucSerialFamily: LOG VERSION;
// Hec495Family: "read all"), and HiPNUC's recovery after a baud change or a reset probes a
// short list without listening. A scan lives in the engine's thread, as its family does.
#include <QObject>
#include <QTimer>

#include <cstdint>
#include <functional>
#include <vector>

namespace imudesk::device {

class BaudScan : public QObject {
    Q_OBJECT
public:
    enum class Outcome {
        Found,   // the device answers at this rate: the scan ends
        TryNext, // nothing usable here: go on with the next rate
        Stop,    // give up without a verdict (the request was cancelled, the link closed)
    };
    // The probe's answer; calls after the scan stopped or moved on are ignored.
    using Answer = std::function<void(Outcome)>;

    struct Plan {
        std::vector<int> bauds;
        int listenMs = 0; // after tuning, before probing
        std::function<void(int baud)> tune;
        std::function<void(int baud, Answer answer)> probe;
        std::function<void(int baud)> found;
        std::function<void()> exhausted; // every rate tried, none found
        std::function<void()> stopped;   // optional: Outcome::Stop
    };

    explicit BaudScan(QObject *parent = nullptr);

    // Starts afresh (a scan under way is dropped without a verdict).
    void start(Plan plan);
    // Ends the scan without a verdict; pending answers are ignored.
    void stop();
    bool running() const { return m_running; }

private:
    void tryAt(size_t index);
    void answered(uint64_t generation, Outcome outcome);

    Plan m_plan;
    QTimer m_listen{this};
    size_t m_index = 0;
    bool m_running = false;
    uint64_t m_generation = 0; // one per rate tried: tells a current answer from a stale one
};

} // namespace imudesk::device
