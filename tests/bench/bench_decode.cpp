// bench_decode: decode throughput of ImuDesk's HiPNUC FrameDecoder against a
// byte-at-a-time reference decoder written in the style of the vendor manual.
//
// The capture is generated in memory from a fixed seed: HI91 frames with varying
// values, 1 % of them damaged (payload byte flipped, CRC byte flipped or frame
// truncated), and 0..40 bytes of garbage between frames, some of it holding lone
// 0x5A bytes and false `5A A5` headers with plausible lengths. The generator knows
// which frames are intact and what every decoder must report, so both decoders are
// checked for lost frames, extra frames, error counts and decoded values.
//
//   bench_decode [--mb N] [--quick] [--runs N] [--seed N] [--chunk N]
//
// MB here is 10^6 bytes. Exit status: 0 when both decoders found every intact frame,
// their decoded values agree and the speed ratio reaches the 5x target; 1 otherwise;
// 2 on bad arguments.
#include "protocol/hipnuc/crc16.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

namespace {

using namespace imudesk::protocol::hipnuc;

constexpr size_t kFrameSize = FrameDecoder::kHeaderSize + Hi91::kSize; // 82
constexpr uint32_t kTimeBase = 100000; // systemTime of frame 0, ms
constexpr uint32_t kTimeStep = 5;      // 200 Hz
constexpr size_t kTailPadding = 512;   // zero bytes after the last frame: every false header is complete

// splitmix64: small, fast and identical on every platform (std distributions are not).
class Rng {
public:
    explicit Rng(uint64_t seed) : m_s(seed) {}
    uint64_t next()
    {
        uint64_t z = (m_s += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    uint32_t below(uint32_t n) { return uint32_t((next() >> 32) * n >> 32); } // 0..n-1
    double unit() { return double(next() >> 11) * 0x1.0p-53; }               // [0, 1)
    double sym() { return unit() * 2.0 - 1.0; }                              // [-1, 1)
    bool chance(double p) { return unit() < p; }

private:
    uint64_t m_s;
};

// Order-dependent digest of every HI91 field; both decoders and the generator use it.
struct ValueDigest {
    uint64_t h = 0xCBF29CE484222325ull;
    void add(uint64_t v) { h = (h ^ v) * 0x100000001B3ull; }
    void add(float f) { add(uint64_t(std::bit_cast<uint32_t>(f))); }
    void add(const Hi91 &p)
    {
        add(uint64_t(p.mainStatus));
        add(uint64_t(uint8_t(p.temperature)));
        add(p.pressure);
        add(uint64_t(p.systemTime));
        for (float f : p.acc) add(f);
        for (float f : p.gyr) add(f);
        for (float f : p.mag) add(f);
        add(p.roll);
        add(p.pitch);
        add(p.yaw);
        for (float f : p.quat) add(f);
    }
};

// ---------------------------------------------------------------------------
// Capture generator

struct Capture {
    std::vector<uint8_t> bytes;
    std::vector<size_t> intactStarts; // offsets of the intact frames, ascending
    uint64_t framesWritten = 0;
    uint64_t intact = 0;
    uint64_t corruptPayload = 0, corruptCrc = 0, truncated = 0;
    uint64_t garbageBytes = 0, garbageGaps = 0, loneSync = 0, fakePlausible = 0, fakeBadLength = 0;
    uint64_t fixups = 0;          // false headers whose random CRC happened to match, defused
    uint64_t expectCrcErrors = 0; // what a decoder that re-scans correctly must count
    uint64_t expectLengthErrors = 0;
    uint64_t expectSkipped = 0;
    uint64_t expectDigest = 0;
};

Hi91 makeSample(uint64_t i, Rng &rng)
{
    const double t = double(i) * kTimeStep * 1e-3;
    Hi91 p;
    p.mainStatus = uint16_t(rng.next() & 0x0FFF);
    p.temperature = int8_t(25 + int(std::lround(3.0 * std::sin(t * 0.01))) + int(rng.below(3)) - 1);
    p.pressure = float(101325.0 + 40.0 * std::sin(t * 0.05) + rng.sym());
    p.systemTime = uint32_t(kTimeBase + i * kTimeStep); // unique per frame: identifies it
    const double roll = 20.0 * std::sin(t * 0.7), pitch = 10.0 * std::sin(t * 0.3 + 1.0);
    const double yaw = std::fmod(t * 3.0, 360.0) - 180.0;
    p.acc = {float(-std::sin(pitch * 0.0174533) + 0.01 * rng.sym()),
             float(std::sin(roll * 0.0174533) + 0.01 * rng.sym()),
             float(std::cos(roll * 0.0174533) * std::cos(pitch * 0.0174533) + 0.01 * rng.sym())};
    p.gyr = {float(14.0 * std::cos(t * 0.7) + 0.2 * rng.sym()), float(3.0 * std::cos(t * 0.3 + 1.0) + 0.2 * rng.sym()),
             float(3.0 + 0.2 * rng.sym())};
    p.mag = {float(22.0 + rng.sym()), float(-4.0 + rng.sym()), float(-41.0 + rng.sym())};
    p.roll = float(roll);
    p.pitch = float(pitch);
    p.yaw = float(yaw);
    const double cr = std::cos(roll * 0.00872665), sr = std::sin(roll * 0.00872665);
    const double cp = std::cos(pitch * 0.00872665), sp = std::sin(pitch * 0.00872665);
    const double cy = std::cos(yaw * 0.00872665), sy = std::sin(yaw * 0.00872665);
    p.quat = {float(cr * cp * cy + sr * sp * sy), float(sr * cp * cy - cr * sp * sy), float(cr * sp * cy + sr * cp * sy),
              float(cr * cp * sy - sr * sp * cy)};
    return p;
}

void appendGarbage(Capture &c, Rng &rng)
{
    const uint32_t n = rng.below(41); // 0..40 bytes
    if (n == 0)
        return;
    ++c.garbageGaps;
    c.garbageBytes += n;
    const size_t at = c.bytes.size();
    c.bytes.resize(at + n);
    uint8_t *g = c.bytes.data() + at;
    for (uint32_t k = 0; k < n; ++k)
        g[k] = uint8_t(rng.next());
    if (rng.chance(0.05)) { // a lone sync byte somewhere
        g[rng.below(n)] = 0x5A;
        ++c.loneSync;
    }
    if (n >= 4 && rng.chance(0.03)) { // a false header; its CRC bytes are random or the next frame's
        const uint32_t pos = rng.below(n - 3);
        uint32_t len;
        if (rng.chance(0.15)) {
            constexpr uint32_t kFirstBad = uint32_t(FrameDecoder::kMaxPayload) + 1;
            len = rng.chance(0.3) ? 0u : kFirstBad + rng.below(65536 - kFirstBad);
            ++c.fakeBadLength;
        } else {
            len = rng.chance(0.5) ? uint32_t(Hi91::kSize) : 1u + rng.below(uint32_t(FrameDecoder::kMaxPayload));
            ++c.fakePlausible;
        }
        g[pos] = 0x5A;
        g[pos + 1] = 0xA5;
        g[pos + 2] = uint8_t(len & 0xFF);
        g[pos + 3] = uint8_t(len >> 8);
    }
}

bool insideIntact(const Capture &c, size_t pos)
{
    auto it = std::upper_bound(c.intactStarts.begin(), c.intactStarts.end(), pos);
    if (it == c.intactStarts.begin())
        return false;
    --it;
    return pos < *it + kFrameSize;
}

// Every `5A A5` outside the intact frames is a candidate a correct decoder examines.
// A candidate whose CRC matches by chance (1 in 65536) would be a real frame by the
// protocol's rules and could hide an intact frame behind it, so it is defused by
// changing its 0xA5 (never part of an intact frame: those start with 0x5A). That can
// change the CRC of an earlier overlapping candidate, hence the loop. The final pass
// yields the error counts both decoders must report.
void defuseAndCount(Capture &c)
{
    for (;;) {
        uint64_t fixed = 0, crcErr = 0, lenErr = 0;
        const uint8_t *b = c.bytes.data();
        const size_t n = c.bytes.size();
        size_t i = 0;
        while (i + 1 < n) {
            const void *hit = std::memchr(b + i, 0x5A, n - i - 1);
            if (!hit)
                break;
            i = size_t(static_cast<const uint8_t *>(hit) - b);
            if (b[i + 1] != 0xA5 || insideIntact(c, i)) {
                ++i;
                continue;
            }
            const size_t len = size_t(b[i + 2]) | (size_t(b[i + 3]) << 8);
            if (len == 0 || len > FrameDecoder::kMaxPayload) {
                ++lenErr;
            } else if (frameCrc(b + i, b + i + FrameDecoder::kHeaderSize, len) == uint16_t(b[i + 4] | (b[i + 5] << 8))) {
                c.bytes[i + 1] = 0xA4;
                ++fixed;
            } else {
                ++crcErr;
            }
            ++i;
        }
        c.fixups += fixed;
        if (fixed == 0) {
            c.expectCrcErrors = crcErr;
            c.expectLengthErrors = lenErr;
            return;
        }
    }
}

Capture generate(uint64_t targetBytes, uint64_t seed)
{
    Capture c;
    c.bytes.reserve(targetBytes + 4096);
    Rng rng(seed);
    ValueDigest digest;
    for (uint64_t i = 0; c.bytes.size() < targetBytes; ++i) {
        appendGarbage(c, rng);
        const Hi91 sample = makeSample(i, rng);
        std::vector<uint8_t> frame = buildFrame(encode(sample));
        ++c.framesWritten;
        if (rng.chance(0.01)) {
            switch (rng.below(3)) {
            case 0: // payload byte flipped (CRC-16 catches every single-byte error)
                frame[FrameDecoder::kHeaderSize + rng.below(Hi91::kSize)] ^= uint8_t(1 + rng.below(255));
                ++c.corruptPayload;
                break;
            case 1:
                frame[4 + rng.below(2)] ^= uint8_t(1 + rng.below(255));
                ++c.corruptCrc;
                break;
            default:
                frame.resize(1 + rng.below(kFrameSize - 1)); // 1..81 bytes survive
                ++c.truncated;
                break;
            }
        } else {
            c.intactStarts.push_back(c.bytes.size());
            ++c.intact;
            digest.add(sample);
        }
        c.bytes.insert(c.bytes.end(), frame.begin(), frame.end());
    }
    c.bytes.insert(c.bytes.end(), kTailPadding, uint8_t(0));
    defuseAndCount(c);
    c.expectSkipped = c.bytes.size() - c.intact * kFrameSize;
    c.expectDigest = digest.h;
    return c;
}

// ---------------------------------------------------------------------------
// Decoders under test

struct Result {
    uint64_t frames = 0;
    uint64_t hi91 = 0;
    uint64_t crcErrors = 0;
    uint64_t lengthErrors = 0;
    uint64_t skipped = 0; // only the FrameDecoder reports it
    uint64_t digest = 0;
    std::vector<uint32_t> ids; // systemTime of each HI91, on the verification run only
};

// Reference: a byte-at-a-time state machine shaped like the decoder in the vendor
// manual (sync window, header, payload byte by byte, then the manual's bit-by-bit CRC
// over header[0..3] + payload). Unlike the manual's code it re-scans on failure: the
// bytes after the failed sync byte are pushed back in front of the input, so a frame
// starting inside a damaged or false frame is still found.
class ManualDecoder {
public:
    explicit ManualDecoder(Result &r, bool record) : m_r(r), m_record(record) { m_replay.reserve(1024); }

    void input(const uint8_t *p, size_t n)
    {
        for (size_t i = 0; i < n; ++i) {
            step(p[i]);
            if (!m_replay.empty())
                drainReplay();
        }
    }

private:
    enum class State { Sync1, Sync2, LenLo, LenHi, CrcLo, CrcHi, Payload };

    void step(uint8_t c)
    {
        switch (m_state) {
        case State::Sync1:
            if (c == 0x5A) {
                m_buf[0] = c;
                m_state = State::Sync2;
            }
            return;
        case State::Sync2:
            if (c == 0xA5) {
                m_buf[1] = c;
                m_state = State::LenLo;
            } else if (c != 0x5A) {
                m_state = State::Sync1; // a second 0x5A is itself a sync candidate: stay
            }
            return;
        case State::LenLo:
            m_buf[2] = c;
            m_state = State::LenHi;
            return;
        case State::LenHi:
            m_buf[3] = c;
            m_len = size_t(m_buf[2]) | (size_t(c) << 8);
            if (m_len == 0 || m_len > kMaxPayload) {
                ++m_r.lengthErrors;
                fail(4);
                return;
            }
            m_state = State::CrcLo;
            return;
        case State::CrcLo:
            m_buf[4] = c;
            m_state = State::CrcHi;
            return;
        case State::CrcHi:
            m_buf[5] = c;
            m_pos = 6;
            m_state = State::Payload;
            return;
        case State::Payload:
            m_buf[m_pos++] = c;
            if (m_pos < 6 + m_len)
                return;
            {
                uint16_t crc = crc16UpdateBitwise(0, m_buf, 4);
                crc = crc16UpdateBitwise(crc, m_buf + 6, m_len);
                const uint16_t rx = uint16_t(m_buf[4] | (m_buf[5] << 8));
                if (crc != rx) {
                    ++m_r.crcErrors;
                    fail(m_pos);
                    return;
                }
            }
            ++m_r.frames;
            parse(m_buf + 6, m_len);
            m_state = State::Sync1;
            return;
        }
    }

    // The candidate at m_buf[0] is dead: re-scan m_buf[1..n) before any later byte.
    void fail(size_t n)
    {
        m_state = State::Sync1;
        m_replay.insert(m_replay.begin(), m_buf + 1, m_buf + n);
    }

    void drainReplay()
    {
        while (!m_replay.empty()) {
            m_scratch.swap(m_replay);
            m_replay.clear();
            size_t k = 0;
            for (; k < m_scratch.size(); ++k) {
                step(m_scratch[k]);
                if (!m_replay.empty()) { // nested failure: its bytes go first, then our rest
                    m_replay.insert(m_replay.end(), m_scratch.begin() + ptrdiff_t(k + 1), m_scratch.end());
                    break;
                }
            }
        }
    }

    // The manual's payload parser: fixed offsets of the HI91 table, copied field by field.
    void parse(const uint8_t *p, size_t len)
    {
        if (p[0] != 0x91 || len != Hi91::kSize)
            return;
        Hi91 h;
        std::memcpy(&h.mainStatus, p + 1, 2);
        std::memcpy(&h.temperature, p + 3, 1);
        std::memcpy(&h.pressure, p + 4, 4);
        std::memcpy(&h.systemTime, p + 8, 4);
        std::memcpy(h.acc.data(), p + 12, 12);
        std::memcpy(h.gyr.data(), p + 24, 12);
        std::memcpy(h.mag.data(), p + 36, 12);
        std::memcpy(&h.roll, p + 48, 4);
        std::memcpy(&h.pitch, p + 52, 4);
        std::memcpy(&h.yaw, p + 56, 4);
        std::memcpy(h.quat.data(), p + 60, 16);
        ++m_r.hi91;
        m_digest.add(h);
        m_r.digest = m_digest.h;
        if (m_record)
            m_r.ids.push_back(h.systemTime);
    }

    static constexpr size_t kMaxPayload = 4096; // the manual's LEN 1-4096 (v1.7.1 5.7)
    Result &m_r;
    bool m_record;
    State m_state = State::Sync1;
    uint8_t m_buf[6 + kMaxPayload];
    size_t m_len = 0, m_pos = 0;
    std::vector<uint8_t> m_replay, m_scratch;
    ValueDigest m_digest;
};

class Hi91Sink : public FrameDecoder::Sink {
public:
    Hi91Sink(Result &r, bool record) : m_r(r), m_record(record) {}
    void onFrame(const uint8_t *payload, size_t len) override
    {
        Hi91 h;
        if (!decodeHi91(payload, len, h))
            return;
        ++m_r.hi91;
        m_digest.add(h);
        if (m_record)
            m_r.ids.push_back(h.systemTime);
    }
    uint64_t digest() const { return m_digest.h; }

private:
    Result &m_r;
    bool m_record;
    ValueDigest m_digest;
};

Result runManual(const std::vector<uint8_t> &data, size_t chunk, bool record)
{
    Result r;
    ManualDecoder d(r, record);
    for (size_t off = 0; off < data.size(); off += chunk)
        d.input(data.data() + off, std::min(chunk, data.size() - off));
    return r;
}

Result runImuDesk(const std::vector<uint8_t> &data, size_t chunk, bool record)
{
    Result r;
    FrameDecoder d;
    Hi91Sink sink(r, record);
    for (size_t off = 0; off < data.size(); off += chunk)
        d.feed(data.data() + off, std::min(chunk, data.size() - off), sink);
    d.finish(sink);
    r.frames = d.counters().frames;
    r.crcErrors = d.counters().crcErrors;
    r.lengthErrors = d.counters().lengthErrors;
    r.skipped = d.counters().bytesSkipped;
    r.digest = sink.digest();
    return r;
}

volatile uint64_t g_observed = 0; // keeps the timed work observable

template <typename F> double bestSeconds(int runs, F &&f)
{
    double best = 1e300;
    for (int k = 0; k < runs; ++k) {
        const auto t0 = std::chrono::steady_clock::now();
        const Result r = f();
        const auto t1 = std::chrono::steady_clock::now();
        g_observed = g_observed + r.digest + r.frames;
        best = std::min(best, std::chrono::duration<double>(t1 - t0).count());
    }
    return best;
}

struct Check {
    uint64_t lost = 0, extra = 0;
};

Check compareIds(const Capture &c, std::vector<uint32_t> ids)
{
    std::vector<uint32_t> want;
    want.reserve(c.intactStarts.size());
    for (size_t start : c.intactStarts) {
        uint32_t t;
        std::memcpy(&t, c.bytes.data() + start + FrameDecoder::kHeaderSize + 8, 4);
        want.push_back(t);
    }
    std::sort(ids.begin(), ids.end());
    Check k;
    std::vector<uint32_t> diff;
    std::set_difference(want.begin(), want.end(), ids.begin(), ids.end(), std::back_inserter(diff));
    k.lost = diff.size();
    diff.clear();
    std::set_difference(ids.begin(), ids.end(), want.begin(), want.end(), std::back_inserter(diff));
    k.extra = diff.size();
    return k;
}

bool parseU64(const char *s, uint64_t &out)
{
    char *end = nullptr;
    errno = 0;
    const unsigned long long v = std::strtoull(s, &end, 0);
    if (!s[0] || *end || errno)
        return false;
    out = v;
    return true;
}

void usage()
{
    std::fprintf(stderr, "usage: bench_decode [--mb N] [--quick] [--runs N>=3] [--seed N] [--chunk BYTES]\n"
                         "  --mb N     capture size in MB (10^6 bytes), default 50\n"
                         "  --quick    5 MB capture, for CI smoke runs\n"
                         "  --runs N   timed runs per decoder, best is reported (default 5, minimum 3)\n"
                         "  --seed N   generator seed (default 0x1D0D5EED)\n"
                         "  --chunk N  FrameDecoder feed size in bytes (default 4096)\n");
}

} // namespace

int main(int argc, char **argv)
{
    uint64_t mb = 50, runs = 5, seed = 0x1D0D5EED, chunk = 4096;
    for (int a = 1; a < argc; ++a) {
        const std::string_view arg = argv[a];
        auto value = [&](uint64_t &out) {
            if (a + 1 >= argc || !parseU64(argv[a + 1], out)) {
                std::fprintf(stderr, "bench_decode: %s needs a number\n", argv[a]);
                std::exit(2);
            }
            ++a;
        };
        if (arg == "--mb") value(mb);
        else if (arg == "--quick") mb = 5;
        else if (arg == "--runs") value(runs);
        else if (arg == "--seed") value(seed);
        else if (arg == "--chunk") value(chunk);
        else if (arg == "-h" || arg == "--help") { usage(); return 0; }
        else { usage(); return 2; }
    }
    if (mb == 0 || mb > 4000 || runs < 3 || runs > 1000 || chunk == 0) {
        usage();
        return 2;
    }

    const auto g0 = std::chrono::steady_clock::now();
    const Capture cap = generate(mb * 1000000ull, seed);
    const double genSec = std::chrono::duration<double>(std::chrono::steady_clock::now() - g0).count();
    const double sizeMB = double(cap.bytes.size()) / 1e6;

    std::printf("bench_decode: %.2f MB capture (%zu bytes), seed 0x%llX, generated in %.2f s\n", sizeMB,
                cap.bytes.size(), (unsigned long long)seed, genSec);
    std::printf("  frames written   %10llu HI91 (%zu bytes each)\n", (unsigned long long)cap.framesWritten, kFrameSize);
    std::printf("    intact         %10llu\n", (unsigned long long)cap.intact);
    std::printf("    damaged        %10llu (payload byte flipped %llu, CRC byte flipped %llu, truncated %llu)\n",
                (unsigned long long)(cap.framesWritten - cap.intact), (unsigned long long)cap.corruptPayload,
                (unsigned long long)cap.corruptCrc, (unsigned long long)cap.truncated);
    std::printf("  garbage          %10llu bytes in %llu gaps of 0..40 bytes, +%zu zero bytes at the end\n",
                (unsigned long long)cap.garbageBytes, (unsigned long long)cap.garbageGaps, kTailPadding);
    std::printf("    lone 0x5A      %10llu\n", (unsigned long long)cap.loneSync);
    std::printf("    false 5A A5    %10llu with plausible length, %llu with length 0 or > %zu (%llu chance CRC matches defused)\n",
                (unsigned long long)cap.fakePlausible, (unsigned long long)cap.fakeBadLength, FrameDecoder::kMaxPayload,
                (unsigned long long)cap.fixups);
    std::printf("  timing: best of %llu runs; FrameDecoder fed in %llu-byte chunks, reference byte by byte\n\n",
                (unsigned long long)runs, (unsigned long long)chunk);

    // Verification runs (untimed): which frames each decoder found.
    const Result vm = runManual(cap.bytes, size_t(chunk), true);
    const Result vi = runImuDesk(cap.bytes, size_t(chunk), true);
    const Check km = compareIds(cap, vm.ids);
    const Check ki = compareIds(cap, vi.ids);

    const double tm = bestSeconds(int(runs), [&] { return runManual(cap.bytes, size_t(chunk), false); });
    const double ti = bestSeconds(int(runs), [&] { return runImuDesk(cap.bytes, size_t(chunk), false); });
    const double mbsM = sizeMB / tm, mbsI = sizeMB / ti;
    const double ratio = mbsI / mbsM;

    auto row = [&](const char *name, double sec, double mbs, const Result &r, const Check &k, const char *skipped) {
        std::printf("%-30s %9.1f %9.1f %9llu %6llu %6llu %8llu %8llu %10s  %016llX\n", name, sec * 1e3, mbs,
                    (unsigned long long)r.frames, (unsigned long long)k.lost, (unsigned long long)k.extra,
                    (unsigned long long)r.crcErrors, (unsigned long long)r.lengthErrors, skipped,
                    (unsigned long long)r.digest);
    };
    std::printf("%-30s %9s %9s %9s %6s %6s %8s %8s %10s  %-16s\n", "decoder", "best ms", "MB/s", "frames", "lost",
                "extra", "CRC err", "len err", "skipped B", "value digest");
    std::printf("%s\n", std::string(120, '-').c_str());
    row("manual state machine (bitwise)", tm, mbsM, vm, km, "-");
    const std::string skippedI = std::to_string(vi.skipped);
    row("ImuDesk FrameDecoder", ti, mbsI, vi, ki, skippedI.c_str());
    std::printf("%-30s %9s %9s %9llu %6d %6d %8llu %8llu %10llu  %016llX\n", "expected (generator)", "-", "-",
                (unsigned long long)cap.intact, 0, 0, (unsigned long long)cap.expectCrcErrors,
                (unsigned long long)cap.expectLengthErrors, (unsigned long long)cap.expectSkipped,
                (unsigned long long)cap.expectDigest);
    std::printf("%s\n", std::string(120, '-').c_str());
    std::printf("speed ratio FrameDecoder / reference: %.2f  (%.1f vs %.1f MB/s)\n\n", ratio, mbsI, mbsM);

    bool ok = true;
    auto fail = [&](const char *what) {
        std::printf("FAIL: %s\n", what);
        ok = false;
    };
    if (km.lost) fail("reference decoder lost intact frames");
    if (ki.lost) fail("FrameDecoder lost intact frames");
    if (km.extra || vm.frames != cap.intact || vm.hi91 != cap.intact) fail("reference decoder frame count differs from the intact frames written");
    if (ki.extra || vi.frames != cap.intact || vi.hi91 != cap.intact) fail("FrameDecoder frame count differs from the intact frames written");
    if (vm.digest != vi.digest) fail("decoded value digests of the two decoders differ");
    if (vi.digest != cap.expectDigest || vm.digest != cap.expectDigest) fail("decoded value digest differs from the generated values");
    if (vm.crcErrors != cap.expectCrcErrors || vi.crcErrors != cap.expectCrcErrors) fail("CRC error count differs from the expected count");
    if (vm.lengthErrors != cap.expectLengthErrors || vi.lengthErrors != cap.expectLengthErrors) fail("length error count differs from the expected count");
    if (vi.skipped != cap.expectSkipped) fail("FrameDecoder skipped-byte count differs from the expected count");
    if (ratio < 5.0) fail("speed ratio below the 5.00 target");

    std::printf("ratio: %.2f (target >= 5.00), intact frames lost: %llu\n", ratio,
                (unsigned long long)(km.lost + ki.lost));
    return ok ? 0 : 1;
}
