#pragma once
// What a session's engine offers a recording as it reads (issue 54 point 2): the bytes received
// and sent with their host times, where the line went idle, and the samples the family decoded.
// The engine knows no file format; record/recording.h has the recordings (a raw capture, an
// MCAP file of one device or of several), which write on threads of their own.
//
// The engine calls a tap in its own thread, only between begin() and end(), and never waits on
// it: an implementation queues what it is given and returns.
#include "capture/capture_header.h"
#include "model/sample.h"

#include <QByteArray>
#include <QString>

#include <cstdint>
#include <functional>
#include <vector>

namespace imudesk::device {

class StreamTap {
public:
    struct Progress {
        uint64_t bytesWritten = 0; // bytes in the file(s) so far
        uint64_t frames = 0;       // frames (a capture) or samples (MCAP) the file holds
    };
    using StoppedHandler = std::function<void(const QString &reason)>;

    virtual ~StreamTap() = default;

    // The link as the engine knows it (identity, link kind, port, baud, the family's entries and
    // the caller's): false, with a message, when the recording cannot start.
    virtual bool begin(const capture::CaptureHeader &header, QString *error) = 0;
    virtual void received(const QByteArray & /*bytes*/, int64_t /*hostNs*/, int64_t /*utcUs*/) {}
    virtual void sent(const QByteArray & /*bytes*/, int64_t /*hostNs*/, int64_t /*utcUs*/) {}
    virtual void lineIdle(int64_t /*hostNs*/, int64_t /*utcUs*/) {}
    virtual void samples(const std::vector<model::Sample> & /*batch*/) {}
    // Read by the engine twice a second (Session::recordingProgress).
    virtual Progress progress() const = 0;
    // Writes what is queued and closes; the error that stopped the recording, or empty.
    virtual QString end() = 0;

    // Called once, from any thread, when the recording stops by itself (a full disk, a removed
    // drive); the engine then ends it and says why (Session::recordingStopped).
    void setStoppedHandler(StoppedHandler handler) { m_stopped = std::move(handler); }

protected:
    void stoppedByItself(const QString &reason) const
    {
        if (m_stopped)
            m_stopped(reason);
    }

private:
    StoppedHandler m_stopped;
};

} // namespace imudesk::device
