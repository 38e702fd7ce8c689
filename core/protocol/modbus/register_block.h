#pragma once
// A run of holding registers as read from a device: the start address and the values.
// Accessors return nullopt for any register outside the block.
#include "register_map.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace imudesk::protocol::modbus {

class RegisterBlock {
public:
    RegisterBlock() = default;
    RegisterBlock(uint16_t start, std::vector<uint16_t> values) : m_start(start), m_values(std::move(values)) {}

    uint16_t start() const { return m_start; }
    size_t size() const { return m_values.size(); }
    const std::vector<uint16_t> &values() const { return m_values; }
    bool contains(uint16_t address, uint16_t words = 1) const;

    std::optional<uint16_t> u16(uint16_t address) const;
    std::optional<int16_t> i16(uint16_t address) const;
    std::optional<int32_t> i32(uint16_t address) const;   // high word first
    std::optional<float> f32le(uint16_t address) const;   // bytes least significant first
    std::optional<std::string> ascii(uint16_t address, uint16_t words) const; // up to the first NUL
    std::optional<std::string> hex(uint16_t address, uint16_t words) const;   // "047D955F8D2A1708"

    // The raw integer of a register (U16/I16/I32), or the float (F32LE), as a double.
    std::optional<double> raw(const RegisterDef &def) const;
    // raw * scale; nullopt for Ascii/Bytes and for registers outside the block.
    std::optional<double> scaled(const RegisterDef &def) const;
    // A display text of the register's value ("0.4609", "HI14R2N-485-000", "047D...").
    std::optional<std::string> text(const RegisterDef &def) const;

    // Encoders (the simulator and tests): register words for a value.
    static std::vector<uint16_t> wordsI32(int32_t v);
    static std::vector<uint16_t> wordsF32le(float v);
    static std::vector<uint16_t> wordsAscii(const std::string &text, uint16_t words);

private:
    uint16_t m_start = 0;
    std::vector<uint16_t> m_values;
};

} // namespace imudesk::protocol::modbus
