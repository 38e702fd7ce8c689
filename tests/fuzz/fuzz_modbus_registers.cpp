// libFuzzer target: Modbus RTU frames and register blocks through ImuDesk's decoders.
//
// Input: byte 0 selects the start address of the block (bits 0-6: 0x00, 0x04, 0x34, 0x70, ...
// from a table; bit 7: HEC495), the rest is one RTU frame (a response from a device).
//   * RtuAdu::parseResponse / parseRequest never crash; an accepted response re-framed gives
//     back the input bytes exactly, and its registers re-encoded give back its PDU.
//   * The rest of the input read as big-endian register words (bounded to 125 words) goes
//     through every decoder: HiPNUC and HEC495 samples, the identity block, and the text of
//     every register of every map; an identity decoded, encoded and decoded again is the same.
//   * I32 and F32 word encoders round-trip.
#include "protocol/modbus/identity_block.h"
#include "protocol/modbus/register_decoder.h"
#include "protocol/modbus/rtu_adu.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>

#define FUZZ_CHECK(cond)                                                                                    \
    do {                                                                                                    \
        if (!(cond)) {                                                                                      \
            std::fprintf(stderr, "fuzz_modbus_registers: invariant failed: %s (line %d)\n", #cond, __LINE__); \
            __builtin_trap();                                                                               \
        }                                                                                                   \
    } while (0)

using namespace imudesk::protocol::modbus;

namespace {

constexpr uint16_t kStarts[] = {0x00, 0x04, 0x05, 0x34, 0x3D, 0x41, 0x70, 0x78, 0x7F, 0xA5};

void decodeEverything(const RegisterBlock &block)
{
    const auto hip = RegisterDecoder::hipnucSample(block);
    const auto hec = RegisterDecoder::hec495Sample(block);
    FUZZ_CHECK(hip.source == RegisterDecoder::kHipnucSource && hec.source == RegisterDecoder::kHec495Source);
    if (hip.has(imudesk::model::FieldEuler))
        FUZZ_CHECK(std::abs(hip.roll) <= 2147483.648 && std::abs(hip.yaw) <= 2147483.648);
    for (const RegisterMap *map : {&RegisterMap::hipnucAll(), &RegisterMap::hec495()})
        for (const RegisterDef &d : map->registers()) {
            const auto text = block.text(d);
            FUZZ_CHECK(text.has_value() == block.contains(d.address, d.words));
        }
    if (const auto id = IdentityBlock::decode(block)) {
        const auto again = IdentityBlock::decode(RegisterBlock(reg::kIdentityStart, id->encode()));
        FUZZ_CHECK(again.has_value());
        FUZZ_CHECK(again->swVersion == id->swVersion && again->blVersion == id->blVersion);
        FUZZ_CHECK(again->serial == id->serial);
        FUZZ_CHECK(again->productName == id->productName);
        (void)id->toDeviceIdentity();
    }
    for (size_t i = 0; i + 1 < block.size(); ++i) {
        const uint16_t a = uint16_t(block.start() + i);
        const int32_t v = *block.i32(a);
        FUZZ_CHECK(*RegisterBlock(0, RegisterBlock::wordsI32(v)).i32(0) == v);
        const float f = *block.f32le(a);
        const float g = *RegisterBlock(0, RegisterBlock::wordsF32le(f)).f32le(0);
        FUZZ_CHECK(std::memcmp(&f, &g, sizeof f) == 0);
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    const uint16_t start = kStarts[(data[0] & 0x7F) % (sizeof kStarts / sizeof kStarts[0])];
    const QByteArray frame(reinterpret_cast<const char *>(data + 1), qsizetype(size - 1));

    const RtuAdu::Parsed req = RtuAdu::parseRequest(frame);
    FUZZ_CHECK(RtuAdu::errorName(req.error) != nullptr);
    const RtuAdu::Parsed resp = RtuAdu::parseResponse(frame);
    if (resp.ok()) {
        FUZZ_CHECK(resp.expectedSize == frame.size());
        FUZZ_CHECK(RtuAdu::frame(resp.serverAddress, resp.response()) == frame);
        if (const auto regs = RtuAdu::readRegisters(resp.response())) {
            FUZZ_CHECK(RtuAdu::readResponse(*regs).data() == resp.data);
            decodeEverything(RegisterBlock(start, *regs));
        }
    }

    // The payload as register words, whatever its framing.
    std::vector<uint16_t> words;
    for (size_t i = 1; i + 1 < size && words.size() < 125; i += 2)
        words.push_back(uint16_t((data[i] << 8) | data[i + 1]));
    decodeEverything(RegisterBlock(start, words));
    return 0;
}
