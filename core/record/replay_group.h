#pragma once
// Replaying a multi-device session (session.json, issue 36) in the window: one ReplaySession
// per device, each on the session's timeline, moved together.
//
// ReplayTimeline puts a capture on the session's clock: positions count from originNs (the
// session's start on the recording host's steady clock, the clock of every capture's chunks)
// instead of the capture's first chunk, so one position is the same instant in every device,
// and the timeline runs to endNs at least. offsetNs (twist to align) is added to every common
// time, as the session's export does.
//
// ReplayGroup links the sessions' transport: play, pause, seek, speed and loop asked of any
// member are done by all of them. "As fast as possible" has no common pace, so a group plays
// at ReplaySession::kMaxSpeed instead. Plain class, GUI thread; a member leaves when destroyed.
#include <cstdint>
#include <vector>

namespace imudesk::record {

class ReplaySession;

struct ReplayTimeline {
    int64_t originNs = 0; // 0: the capture's own first chunk
    int64_t endNs = 0;    // 0: the capture's last chunk
    int64_t offsetNs = 0;
};

class ReplayGroup {
public:
    void add(ReplaySession *member);
    void remove(ReplaySession *member);
    const std::vector<ReplaySession *> &members() const { return m_members; }

    void play();
    void pause();
    void seek(double seconds);
    void setSpeed(double factor);
    void setLoop(bool on);

private:
    std::vector<ReplaySession *> m_members;
};

} // namespace imudesk::record
