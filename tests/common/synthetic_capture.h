#pragma once
// Builds capture files of simulated HiPNUC frames for tests and benchmarks: HI91 at a
// fixed rate with deterministic pseudo-random values, optionally HI81/HI83 frames and NMEA
// sentences in between, grouped into chunks the way a UART read delivers them.
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"
#include "capture/capture_format.h"

#include <QFile>
#include <QString>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <algorithm>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace synthetic {

struct CaptureSpec {
    uint64_t frames = 1000;      // HI91 frames
    double rateHz = 1000;
    int framesPerChunk = 8;      // a 921600-baud read holds a few frames
    bool mixed = false;          // add HI81 and HI83 (every 10th frame) and RMC (every 100th)
    uint32_t seed = 1;
    int64_t t0Ns = 5'000'000'000; // host time of the first frame's start (the chunks' clock)
    std::string serial;                          // device.serial in the header; empty: none
    std::map<std::string, std::string> config;   // the header's configuration snapshot
    std::string linkKind;                        // link.kind in the header; empty: none (HiPNUC serial)
    // As a module has them: a status word that stays while nothing happens and a barometer that
    // reads at its own rate (a new value every pressureEveryFrames frames, the last one repeated
    // in between). 1 and 1: both change every frame (the decoders' tests).
    int statusEveryFrames = 1;
    int pressureEveryFrames = 1;
};

inline imudesk::protocol::hipnuc::Hi91 hi91(uint64_t i, std::mt19937 &rng, double rateHz, int statusEveryFrames = 1,
                                            int pressureEveryFrames = 1)
{
    std::normal_distribution<float> noise(0.f, 0.01f);
    imudesk::protocol::hipnuc::Hi91 h;
    h.mainStatus = uint16_t(0x1508 + (i / uint64_t(std::max(1, statusEveryFrames))) % 3);
    h.temperature = int8_t(25 + (i / 1000) % 10);
    // The barometer's reading of frame i: its own noise, the same for the frames it spans.
    const uint64_t reading = i / uint64_t(std::max(1, pressureEveryFrames));
    h.pressure = 100676.07f + (pressureEveryFrames <= 1 ? noise(rng)
                                                        : float(int64_t((reading * 2654435761u) % 4001u) - 2000) * 1e-5f);
    h.systemTime = uint32_t(double(i) * 1000.0 / rateHz);
    h.acc = {noise(rng), noise(rng), 1.0f + noise(rng)};
    h.gyr = {0.1f + noise(rng), -0.2f + noise(rng), noise(rng)};
    h.mag = {20.f + noise(rng), -5.f + noise(rng), 40.f + noise(rng)};
    h.roll = 1.5f + noise(rng);
    h.pitch = -0.5f + noise(rng);
    h.yaw = float(std::fmod(double(i) * 0.01, 360.0));
    h.quat = {0.99f, 0.01f + noise(rng), -0.02f, 0.1f};
    return h;
}

// Writes the capture; returns the number of bytes, 0 on failure.
inline qint64 writeCapture(const QString &path, const CaptureSpec &spec)
{
    namespace hp = imudesk::protocol::hipnuc;
    namespace cap = imudesk::capture;
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return 0;
    imudesk::capture::CaptureHeader header;
    header.set(imudesk::capture::CaptureHeader::kProduct, "HI14R3");
    header.set(imudesk::capture::CaptureHeader::kBaud, "921600");
    if (!spec.serial.empty())
        header.set(imudesk::capture::CaptureHeader::kSerial, spec.serial);
    if (!spec.linkKind.empty())
        header.set(imudesk::capture::CaptureHeader::kLinkKind, spec.linkKind);
    header.setConfig(spec.config);
    auto bytes = cap::encodeFileHeader(header);
    f.write(reinterpret_cast<const char *>(bytes.data()), qint64(bytes.size()));
    std::mt19937 rng(spec.seed);
    std::vector<uint8_t> chunk, out;
    const int64_t t0 = spec.t0Ns;
    int inChunk = 0;
    for (uint64_t i = 0; i < spec.frames; ++i) {
        const auto frame =
            hp::buildFrame(hp::encode(hi91(i, rng, spec.rateHz, spec.statusEveryFrames, spec.pressureEveryFrames)));
        chunk.insert(chunk.end(), frame.begin(), frame.end());
        if (spec.mixed && i % 10 == 5) {
            hp::Hi81 h81;
            h81.mainStatus = 7;
            h81.gyr = {int16_t(i % 100), -3, 4};
            h81.acc = {10, 20, 2000};
            h81.lat = 311250000;
            h81.lon = 1214583333;
            h81.velEnu = {1, 2, -3};
            const auto f81 = hp::buildFrame(hp::encode(h81));
            chunk.insert(chunk.end(), f81.begin(), f81.end());
            hp::Hi83 h83;
            h83.bitmap = hp::Hi83::kDefaultMap | (1u << 9);
            h83.accB = {0.1f, 0.2f, 9.8f};
            h83.systemTimeUs = i * 1000;
            h83.inclination = {1.f, 2.f, 3.f};
            const auto f83 = hp::buildFrame(hp::encode(h83));
            chunk.insert(chunk.end(), f83.begin(), f83.end());
        }
        if (spec.mixed && i % 100 == 50) {
            const char *rmc = "$GPRMC,235952.00,A,3112.5000,N,12127.5000,E,0.0,0.0,141125,0.0,E,A*3B\r\n";
            chunk.insert(chunk.end(), rmc, rmc + std::strlen(rmc));
        }
        if (++inChunk == spec.framesPerChunk || i + 1 == spec.frames) {
            const int64_t t = t0 + int64_t(double(i + 1) * 1e9 / spec.rateHz);
            cap::appendChunk(out, cap::ChunkReceived, t, 1'700'000'000'000'000 + t / 1000, chunk.data(),
                             chunk.size());
            chunk.clear();
            inChunk = 0;
            if (out.size() > (1u << 20)) {
                f.write(reinterpret_cast<const char *>(out.data()), qint64(out.size()));
                out.clear();
            }
        }
    }
    f.write(reinterpret_cast<const char *>(out.data()), qint64(out.size()));
    return f.size();
}

} // namespace synthetic
