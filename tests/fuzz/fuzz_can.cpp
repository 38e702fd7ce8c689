// libFuzzer target: the CAN decoders (J1939 data and configuration, CANopen TPDO / SDO / NMT /
// heartbeat, HEC495 PDOs and SDO writes, the frame classifier, the segmented SDO download, and the
// simulated CAN bootloader's side of it, which keeps its state from one input to the next).
//
// Input layout: byte 0 = flags (bit 0 extended, bit 1 CAN FD, bit 2 remote, bits 4..5 the
// classifier's protocol), bytes 1..4 = identifier (LE, masked to 29 or 11 bits), the rest =
// data (at most 8 bytes classic, 64 FD). Whatever the frame, nothing may crash, and what
// decodes must encode back to frames that decode to the same values.
#include "protocol/can/can_decoder.h"
#include "protocol/can/canopen.h"
#include "protocol/can/hec495_can.h"
#include "protocol/can/j1939.h"
#include "protocol/can/j1939_config.h"
#include "protocol/can/sdo.h"
#include "protocol/can/sdo_segmented_download.h"
#include "sim/can_bootloader.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>

#define FUZZ_CHECK(cond)                                                                       \
    do {                                                                                       \
        if (!(cond)) {                                                                         \
            std::fprintf(stderr, "fuzz_can: invariant failed: %s (line %d)\n", #cond, __LINE__); \
            __builtin_trap();                                                                  \
        }                                                                                      \
    } while (0)

using namespace imudesk::protocol::can;
using imudesk::model::Sample;

namespace {

bool sameOrBothNan(double a, double b)
{
    return a == b || (std::isnan(a) && std::isnan(b));
}

bool sameSample(const Sample &a, const Sample &b)
{
    return a.fields == b.fields && a.acc == b.acc && a.gyr == b.gyr && a.mag == b.mag && a.roll == b.roll
        && a.pitch == b.pitch && a.yaw == b.yaw && a.quat == b.quat && a.pressurePa == b.pressurePa
        && a.inclinationX == b.inclinationX && a.inclinationY == b.inclinationY && a.temperatureC == b.temperatureC
        && a.deviceTimeMs == b.deviceTimeMs && a.mainStatus == b.mainStatus;
}

void checkJ1939(const CanFrame &f)
{
    const auto r = j1939::decodeData(f);
    FUZZ_CHECK(j1939::errorName(r.error) != nullptr);
    if (r.ok()) {
        FUZZ_CHECK(f.extended && j1939::isDataPgn(r.data.pgn) && f.len >= j1939::minimumLength(r.data.pgn));
        if (r.data.pgn == j1939::PgnTime) {
            FUZZ_CHECK(r.data.time.has_value());
            const CanFrame back = j1939::encodeTime(r.data.sourceAddress, *r.data.time);
            FUZZ_CHECK(j1939::decodeData(back).data.time == r.data.time);
        } else if (r.data.pgn != j1939::PgnHeading) {
            // Re-encoding the decoded values gives a frame that decodes to the same values.
            const CanFrame back = j1939::encodeData(r.data.pgn, r.data.sourceAddress, r.data.sample);
            const auto again = j1939::decodeData(back);
            FUZZ_CHECK(again.ok());
            FUZZ_CHECK(sameSample(again.data.sample, r.data.sample));
        } else {
            FUZZ_CHECK(r.data.sample.yaw > -180.0 - 1e-9 && r.data.sample.yaw <= 180.0 + 1e-9);
        }
    }
    if (const auto m = j1939::parseReg(f)) {
        const CanFrame back = j1939::encodeReg(*m);
        FUZZ_CHECK(std::memcmp(back.data.data(), f.data.data(), 8) == 0);
        FUZZ_CHECK(j1939::parseReg(back) == m);
        (void)j1939::describe(*m);
    }
}

void checkCanOpen(const CanFrame &f)
{
    const auto t = canopen::decodeTpdo(f);
    if (t.ok()) {
        FUZZ_CHECK(!f.extended && f.len == canopen::tpdoLength(t.channel));
        const CanFrame back = canopen::encodeTpdo(t.channel, t.node, t.sample);
        FUZZ_CHECK(back.id == f.id && back.len == f.len);
        FUZZ_CHECK(std::memcmp(back.data.data(), f.data.data(), f.len) == 0);
    }
    if (const auto s = canopen::parseSdo(f)) {
        FUZZ_CHECK(f.len == 8 && s->node >= 1 && s->node <= 127);
        FUZZ_CHECK(s->size >= 0 && s->size <= 4);
        if (s->size > 0 && s->size < 4)
            FUZZ_CHECK((s->value >> (8 * s->size)) == 0);
        (void)canopen::describe(*s);
        if (s->kind == canopen::SdoKind::Abort)
            FUZZ_CHECK(!canopen::abortText(s->value).isEmpty());
    }
    if (const auto n = canopen::parseNmt(f))
        FUZZ_CHECK(canopen::encodeNmt(canopen::NmtCommand(n->command), n->node) == f);
    if (const auto h = canopen::parseHeartbeat(f))
        FUZZ_CHECK(canopen::encodeHeartbeat(h->node, h->state) == f);
}

void checkHec495(const CanFrame &f)
{
    for (int mode : {-1, 0, 1})
        if (const auto p = hec495::decodePdo(f, mode)) {
            FUZZ_CHECK(p->slot >= 0 && p->slot < hec495::kPdoCount && p->node >= 1);
            const CanFrame back = hec495::encodePdo(p->slot, p->node, p->sample, p->fixed);
            const auto again = hec495::decodePdo(back, p->fixed ? 1 : 0);
            FUZZ_CHECK(again && again->slot == p->slot);
            if (p->fixed) {
                // The wire's heading field reaches ±655.35; the sample holds it wrapped (yaw
                // ±180, heading 0..360), so the wrap may round the last bit of a heading outside
                // ±180: the yaw agrees to 1e-9 deg, everything else exactly, and the frame made
                // again is canonical (it makes itself again, to the byte).
                Sample a = again->sample, b = p->sample;
                FUZZ_CHECK(std::abs(std::remainder(a.yaw - b.yaw, 360.0)) < 1e-9);
                FUZZ_CHECK(std::abs(std::remainder(a.headingDeg - b.headingDeg, 360.0)) < 1e-9);
                a.yaw = b.yaw;
                FUZZ_CHECK(sameSample(a, b));
                const CanFrame canonical = hec495::encodePdo(again->slot, again->node, again->sample, true);
                FUZZ_CHECK(std::memcmp(canonical.data.data(), back.data.data(), 8) == 0);
            } else {
                // floats: NaN stays NaN, everything else exactly.
                FUZZ_CHECK(sameOrBothNan(again->sample.pitch, p->sample.pitch));
                FUZZ_CHECK(sameOrBothNan(again->sample.acc.x, p->sample.acc.x));
            }
        }
    if (const auto e = hec495::decodeExtended(f)) {
        const CanFrame back = hec495::encodeExtended(e->slot == 1, e->sample);
        const auto again = hec495::decodeExtended(back);
        FUZZ_CHECK(again && sameSample(again->sample, e->sample));
    }
    if (const auto w = hec495::parseWrite(f)) {
        const CanFrame back = w->reply ? hec495::writeReply(w->node, w->index, w->extended)
                                       : hec495::writeRequest(w->node, w->index, w->value, w->extended);
        FUZZ_CHECK(back.id == f.id);
        (void)hec495::describeObject(w->index, w->value);
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 5)
        return 0;
    const uint8_t flags = data[0];
    uint32_t id = 0;
    std::memcpy(&id, data + 1, 4);
    const bool ext = flags & 1;
    const bool fd = flags & 2;
    CanFrame f = CanFrame::fromBytes(ext ? (id & 0x1FFFFFFF) : (id & 0x7FF), ext, data + 5, size - 5, fd);
    f.remote = flags & 4;
    FUZZ_CHECK(f.len <= (fd ? 64 : 8));

    checkJ1939(f);
    checkCanOpen(f);
    checkHec495(f);

    static const CanProtocol protocols[] = {CanProtocol::Auto, CanProtocol::J1939, CanProtocol::CanOpen, CanProtocol::Hec495};
    CanDecoder dec(protocols[(flags >> 4) & 3]);
    const DecodedFrame d = dec.decode(f);
    FUZZ_CHECK(!d.meaning.isEmpty());
    FUZZ_CHECK(d.sample.has_value() == (d.components != 0 || (d.sample && d.sample->fields == 0)));
    const auto &c = dec.counters();
    FUZZ_CHECK(c.frames == 1 && c.dataFrames + c.configFrames + c.unknownFrames == 1);

    // A segmented download fed this frame as the device's reply never overruns its image.
    canopen::SdoSegmentedDownload dl(uint8_t(f.id & 0x7F), 0x1F51, 1, std::vector<uint8_t>(20, 0xA5));
    dl.start();
    for (int i = 0; i < 4; ++i)
        dl.onFrame(f);
    FUZZ_CHECK(dl.sent() <= dl.total());

    // The simulated CAN bootloader taking this frame as a host request: it never writes outside
    // its flash and only answers with classic 8-byte SDO replies of its node.
    static imudesk::sim::CanBootloader boot([] {
        imudesk::sim::CanBootloader::Options o;
        o.flashSize = 64 * 1024;
        o.eraseUsPerSector = 0;
        return o;
    }());
    static int64_t t = 0;
    if (boot.stats().starts == 0)
        boot.start(8, t);
    if (const auto m = canopen::parseSdo(f)) {
        boot.handle(*m, f, t);
        t += 1000;
        for (const CanFrame &r : boot.takeDue(t))
            FUZZ_CHECK(r.id == 0x588 && r.len == 8 && !r.extended);
        if (boot.takeRequest(t) != imudesk::sim::CanBootloader::Request::None)
            boot.start(8, t);
    }
    FUZZ_CHECK(boot.flash().size() == 64 * 1024);
    return 0;
}
