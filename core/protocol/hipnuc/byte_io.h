#pragma once
// Little-endian readers and writers over byte buffers (no alignment assumptions).
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

namespace imudesk::protocol {

class LeReader {
public:
    LeReader(const uint8_t *p, size_t n) : m_p(p), m_n(n) {}
    template <typename T> T get()
    {
        static_assert(std::is_trivially_copyable_v<T>);
        T v{};
        if (m_pos + sizeof(T) <= m_n)
            std::memcpy(&v, m_p + m_pos, sizeof(T)); // hosts are little-endian (x86, ARM)
        m_pos += sizeof(T);
        return v;
    }
    template <typename T, size_t N> void get(std::array<T, N> &a)
    {
        for (auto &x : a)
            x = get<T>();
    }
    size_t pos() const { return m_pos; }
    bool overrun() const { return m_pos > m_n; }

private:
    const uint8_t *m_p;
    size_t m_n;
    size_t m_pos = 0;
};

class LeWriter {
public:
    explicit LeWriter(std::vector<uint8_t> &out) : m_out(out) {}
    template <typename T> void put(T v)
    {
        static_assert(std::is_trivially_copyable_v<T>);
        const size_t at = m_out.size();
        m_out.resize(at + sizeof(T));
        std::memcpy(m_out.data() + at, &v, sizeof(T));
    }
    template <typename T, size_t N> void put(const std::array<T, N> &a)
    {
        for (const auto &x : a)
            put<T>(x);
    }

private:
    std::vector<uint8_t> &m_out;
};

static_assert(std::endian::native == std::endian::little, "ImuDesk assumes a little-endian host");

} // namespace imudesk::protocol
