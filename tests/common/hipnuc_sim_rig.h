#pragma once
// The in-process rig of the HipnucSimulator tests (tst_hipnuc_simulator*.cpp): a simulator
// driven by commands with everything it sent captured and split by the core stream
// demultiplexer, and the helpers those tests share.
#include "core/firmware/update_flow.h"
#include "model/device_identity.h"
#include "model/main_status.h"
#include "model/sample.h"
#include "protocol/hipnuc/ascii_reply.h"
#include "protocol/hipnuc/crc16.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"
#include "protocol/nmea/nmea_parser.h"
#include "protocol/stream/stream_demux.h"
#include "sim/hipnuc_simulator.h"
#include "sim/simulated_byte_link.h"

#include <QTest>

#include <cmath>

Q_DECLARE_METATYPE(imudesk::sim::Motion)

namespace imudesk::test::hipnuc_sim {

using namespace imudesk;
using namespace imudesk::sim;
using namespace imudesk::protocol::hipnuc;
using model::MainStatus;

// Everything the module sent during one step, split by the core stream demultiplexer.
struct Capture {
    std::vector<uint8_t> raw;
    std::vector<std::string> lines;
    std::vector<std::vector<uint8_t>> frames; // payloads
    std::vector<protocol::nmea::Sentence> sentences;
    int nmeaErrors = 0;

    template <typename T> std::vector<T> packets() const
    {
        std::vector<T> out;
        for (const auto &f : frames) {
            const PayloadResult r = decodePayload(f);
            if (!r.ok())
                continue;
            for (const auto &p : r.packets)
                if (const T *t = std::get_if<T>(&p))
                    out.push_back(*t);
        }
        return out;
    }
    int countTag(uint8_t tag) const
    {
        int n = 0;
        for (const auto &f : frames)
            n += !f.empty() && f[0] == tag;
        return n;
    }
    int countSentences(const std::string &type) const
    {
        int n = 0;
        for (const auto &s : sentences)
            n += s.type == type;
        return n;
    }
    std::string text() const { return std::string(raw.begin(), raw.end()); }
};

class Rig {
public:
    explicit Rig(SimOptions o = {}) : sim(std::move(o)) {}

    Capture run(int64_t us)
    {
        sim.advanceTo(sim.nowUs() + us);
        return collect();
    }
    Capture collect()
    {
        Capture c;
        c.raw = sim.takeOutput();
        for (auto &e : demux.feed(c.raw.data(), c.raw.size())) {
            switch (e.kind) {
            case protocol::StreamEvent::Kind::Frame: c.frames.push_back(std::move(e.payload)); break;
            case protocol::StreamEvent::Kind::Line: c.lines.push_back(e.text); break;
            case protocol::StreamEvent::Kind::Nmea:
                c.sentences.push_back(*protocol::nmea::parseSentence(e.text).sentence);
                break;
            case protocol::StreamEvent::Kind::NmeaError: ++c.nmeaErrors; break;
            }
        }
        return c;
    }
    Capture send(const std::string &line, int64_t waitUs = 100000)
    {
        sim.receive(line + "\r\n");
        demux.endQuarantine(); // as the session does: the reply follows the command
        return run(waitUs);
    }
    // Sends a command and collects its reply; Pending status means silence.
    AsciiReply command(const std::string &line, int64_t waitUs = 100000)
    {
        last = send(line, waitUs);
        ReplyCollector rc(line);
        for (const auto &l : last.lines)
            if (rc.addLine(l))
                break;
        return rc.take();
    }
    bool ok(const std::string &line, int64_t waitUs = 100000) { return command(line, waitUs).ok(); }
    // Output off, buffer drained: later raw bytes are replies only.
    void quiet()
    {
        QVERIFY(ok("LOG DISABLE"));
        run(100000);
    }

    HipnucSimulator sim;
    protocol::StreamDemux demux;
    Capture last;
};

inline SimOptions opts(const std::string &firmware = "1.7.1", const std::string &model = "HI14", Motion motion = Motion::Static,
                int baud = 115200)
{
    SimOptions o;
    o.firmware = firmware;
    o.model = model;
    o.motion = motion;
    o.baud = baud;
    return o;
}

inline std::string outcome(const AsciiReply &r)
{
    switch (r.status) {
    case AsciiReply::Status::Ok: return "OK";
    case AsciiReply::Status::Refused: return "ERR";
    case AsciiReply::Status::Pending: return "-";
    default: return "?";
    }
}

inline double angleDiff(double a, double b)
{
    double d = std::fmod(a - b, 360.0);
    if (d > 180.0) d -= 360.0;
    if (d < -180.0) d += 360.0;
    return d;
}

inline Eigen::Vector3d vec(const std::array<float, 3> &a)
{
    return {a[0], a[1], a[2]};
}

inline uint16_t bit(MainStatus::Bit b)
{
    return uint16_t(1u << b);
}

inline SimOptions withFaults(const SimFaults &faults, SimOptions o = opts())
{
    o.faults = faults;
    return o;
}

// Standard deviation of each axis of the HI91 gyro readings, averaged over the axes.
inline double gyroStd(const std::vector<Hi91> &frames)
{
    Eigen::Vector3d sum = Eigen::Vector3d::Zero(), squares = Eigen::Vector3d::Zero();
    for (const Hi91 &h : frames) {
        sum += vec(h.gyr);
        squares += vec(h.gyr).cwiseProduct(vec(h.gyr));
    }
    const double n = double(frames.size());
    const Eigen::Vector3d variance = squares / n - (sum / n).cwiseProduct(sum / n);
    return variance.cwiseSqrt().mean();
}

// Starts (or restarts) an MCAL with the output off, polls LOG MCAL STAT every 100 ms of
// simulated time until it ends (STAT 3 or 4) or limitS pass, and turns the output on again.
// Returns STAT, PROGRESS and the simulated seconds from START to the first poll that saw the end.
struct McalEnd {
    int stat = 0, progress = 0;
    double seconds = -1;
};
inline McalEnd runMagCal(Rig &rig, double limitS = 130)
{
    McalEnd end;
    if (!rig.ok("LOG DISABLE") || !rig.ok("CONFIG MCAL START", 10000))
        return end;
    const int64_t startUs = rig.sim.nowUs() - 10000;
    while (rig.sim.nowUs() - startUs < int64_t(limitS * 1e6)) {
        rig.run(90000);
        const AsciiReply r = rig.command("LOG MCAL STAT", 10000);
        end.stat = std::stoi(r.values.at("STAT"));
        end.progress = std::stoi(r.values.at("PROGRESS"));
        if (end.stat >= 3) {
            end.seconds = double(rig.sim.nowUs() - startUs) * 1e-6;
            break;
        }
    }
    rig.ok("LOG ENABLE");
    return end;
}

} // namespace imudesk::test::hipnuc_sim
