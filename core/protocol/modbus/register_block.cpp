#include "register_block.h"

#include <cmath>
#include <cstdio>
#include <cstring>

namespace imudesk::protocol::modbus {

bool RegisterBlock::contains(uint16_t address, uint16_t words) const
{
    return address >= m_start && size_t(address - m_start) + words <= m_values.size();
}

std::optional<uint16_t> RegisterBlock::u16(uint16_t address) const
{
    if (!contains(address))
        return std::nullopt;
    return m_values[address - m_start];
}

std::optional<int16_t> RegisterBlock::i16(uint16_t address) const
{
    const auto v = u16(address);
    if (!v)
        return std::nullopt;
    return int16_t(*v);
}

std::optional<int32_t> RegisterBlock::i32(uint16_t address) const
{
    if (!contains(address, 2))
        return std::nullopt;
    const uint32_t hi = m_values[address - m_start];
    const uint32_t lo = m_values[address - m_start + 1];
    return int32_t((hi << 16) | lo);
}

std::optional<float> RegisterBlock::f32le(uint16_t address) const
{
    if (!contains(address, 2))
        return std::nullopt;
    // Wire bytes b0 b1 b2 b3 (register 0 = b0 b1, register 1 = b2 b3) are the float's bytes,
    // least significant first.
    const uint16_t r0 = m_values[address - m_start];
    const uint16_t r1 = m_values[address - m_start + 1];
    const uint32_t bits = uint32_t(r0 >> 8) | (uint32_t(r0 & 0xFF) << 8) | (uint32_t(r1 >> 8) << 16)
        | (uint32_t(r1 & 0xFF) << 24);
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

std::optional<std::string> RegisterBlock::ascii(uint16_t address, uint16_t words) const
{
    if (!contains(address, words))
        return std::nullopt;
    std::string s;
    for (uint16_t i = 0; i < words; ++i) {
        const uint16_t w = m_values[address - m_start + i];
        for (const char c : {char(w >> 8), char(w & 0xFF)}) {
            if (c == '\0')
                return s;
            s.push_back((c >= 0x20 && c < 0x7F) ? c : '?');
        }
    }
    return s;
}

std::optional<std::string> RegisterBlock::hex(uint16_t address, uint16_t words) const
{
    if (!contains(address, words))
        return std::nullopt;
    std::string s;
    char buf[8];
    for (uint16_t i = 0; i < words; ++i) {
        std::snprintf(buf, sizeof buf, "%04X", unsigned(m_values[address - m_start + i]));
        s += buf;
    }
    return s;
}

std::optional<double> RegisterBlock::raw(const RegisterDef &def) const
{
    switch (def.type) {
    case RegType::U16:
        if (auto v = u16(def.address))
            return double(*v);
        return std::nullopt;
    case RegType::I16:
        if (auto v = i16(def.address))
            return double(*v);
        return std::nullopt;
    case RegType::I32:
        if (auto v = i32(def.address))
            return double(*v);
        return std::nullopt;
    case RegType::F32LE:
        if (auto v = f32le(def.address))
            return double(*v);
        return std::nullopt;
    case RegType::Ascii:
    case RegType::Bytes:
        return std::nullopt;
    }
    return std::nullopt;
}

std::optional<double> RegisterBlock::scaled(const RegisterDef &def) const
{
    const auto r = raw(def);
    if (!r)
        return std::nullopt;
    return *r * def.scale;
}

std::optional<std::string> RegisterBlock::text(const RegisterDef &def) const
{
    if (def.type == RegType::Ascii)
        return ascii(def.address, def.words);
    if (def.type == RegType::Bytes)
        return hex(def.address, def.words);
    const auto v = scaled(def);
    if (!v)
        return std::nullopt;
    char buf[48];
    if (def.scale == 1.0 && def.type != RegType::F32LE)
        std::snprintf(buf, sizeof buf, "%.0f", *v);
    else
        std::snprintf(buf, sizeof buf, "%.*f", def.scale < 0.001 ? 5 : 4, *v);
    return std::string(buf);
}

std::vector<uint16_t> RegisterBlock::wordsI32(int32_t v)
{
    const uint32_t u = uint32_t(v);
    return {uint16_t(u >> 16), uint16_t(u & 0xFFFF)};
}

std::vector<uint16_t> RegisterBlock::wordsF32le(float v)
{
    uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    const uint8_t b0 = bits & 0xFF, b1 = (bits >> 8) & 0xFF, b2 = (bits >> 16) & 0xFF, b3 = bits >> 24;
    return {uint16_t((b0 << 8) | b1), uint16_t((b2 << 8) | b3)};
}

std::vector<uint16_t> RegisterBlock::wordsAscii(const std::string &text, uint16_t words)
{
    std::vector<uint16_t> out(words, 0);
    for (size_t i = 0; i < text.size() && i < size_t(words) * 2; ++i) {
        const uint16_t c = uint8_t(text[i]);
        out[i / 2] |= (i % 2 == 0) ? uint16_t(c << 8) : c;
    }
    return out;
}

} // namespace imudesk::protocol::modbus
