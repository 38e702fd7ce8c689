#pragma once
// Plays a capture file (docs/FILE_FORMATS.md, "Capture file format") as if the device were connected:
// the recorded bytes go through the live session's decoder path (StreamDemux, HiPNUC
// payloads) into the same bounded SampleStore, so charts, the attitude view and the
// values table work unchanged. Play/pause, speed 0.1x to 10x or as fast as possible,
// seek on the capture's timeline, loop. Samples carry the recorded arrival time as
// hostTimeNs. The worker runs in a private thread; all calls are queued.
#include "device/device_link.h"
#include "capture/capture_header.h"
#include "record/replay_group.h"

#include <QThread>

#include <memory>

namespace imudesk::record {

class ReplayWorker;

class ReplaySession : public device::DeviceLink {
    Q_OBJECT
public:
    static constexpr double kMinSpeed = 0.1;
    static constexpr double kMaxSpeed = 10.0;
    static constexpr double kAsFastAsPossible = 0.0;

    explicit ReplaySession(QObject *parent = nullptr);
    ~ReplaySession() override;

    // Opens a capture: state Opening, then Connected and opened(duration, header), or Failed.
    // Playback starts paused at 0 s. A session's capture opens on the session's timeline
    // (replay_group.h).
    void open(const QString &path, const ReplayTimeline &timeline = {});
    // Joins a group whose members play, pause, seek and change speed together: the calls
    // below then act on every member. The group lives as long as its last member.
    void setGroup(std::shared_ptr<ReplayGroup> group);
    ReplayGroup *group() const { return m_group.get(); }
    void close() override;
    QString linkKind() const override { return m_linkKind; }
    bool isLive() const override { return false; }

    void play();
    void pause();
    // Clamped to kMinSpeed..kMaxSpeed; kAsFastAsPossible (0) decodes without pacing.
    void setSpeed(double factor);
    void seek(double seconds);
    void setLoop(bool on);

Q_SIGNALS:
    void opened(double durationS, const imudesk::capture::CaptureHeader &header);
    void positionChanged(double seconds);
    void playingChanged(bool playing);
    void finished(); // reached the end (not looping)
    void nmeaReceived(const QString &sentence);

private:
    QString m_linkKind = QStringLiteral("replay");
    friend class ReplayGroup;
    void playAlone();
    void pauseAlone();
    void setSpeedAlone(double factor);
    void seekAlone(double seconds);
    void setLoopAlone(bool on);

    std::shared_ptr<ReplayGroup> m_group;
    QThread m_thread;
    ReplayWorker *m_worker = nullptr;
};

} // namespace imudesk::record
