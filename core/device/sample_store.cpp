#include "sample_store.h"

#include "clock/host_clock.h"

#include <algorithm>
#include <bit>

namespace imudesk::device {

SampleStore::SampleStore(size_t capacity) : m_capacity(std::max<size_t>(1, capacity))
{
    m_ring.reserve(std::min<size_t>(m_capacity, 4096));
}

void SampleStore::append(const std::vector<model::Sample> &batch)
{
    std::lock_guard lock(m_mutex);
    for (const auto &s : batch) {
        if (m_ring.size() < m_capacity)
            m_ring.push_back(s);
        else
            m_ring[m_total % m_capacity] = s;
        ++m_total;
        model::mergeFields(m_perField, s);
        for (uint32_t f = s.fields; f != 0; f &= f - 1)
            m_fieldTimes[size_t(std::countr_zero(f))] = s.hostTimeNs;
    }
}

SampleStore::FieldAges SampleStore::fieldAges() const
{
    const int64_t now = hostNowNs();
    std::lock_guard lock(m_mutex);
    FieldAges ages{};
    for (size_t f = 0; f < ages.size(); ++f)
        ages[f] = m_fieldTimes[f] > 0 ? double(now - m_fieldTimes[f]) / 1e9 : 0.0;
    return ages;
}

void SampleStore::clear()
{
    std::lock_guard lock(m_mutex);
    m_ring.clear();
    m_total = 0;
    m_perField = model::Sample{};
    m_fieldTimes = {};
}

uint64_t SampleStore::totalAppended() const
{
    std::lock_guard lock(m_mutex);
    return m_total;
}

size_t SampleStore::size() const
{
    std::lock_guard lock(m_mutex);
    return m_ring.size();
}

std::optional<model::Sample> SampleStore::latestPerField() const
{
    std::lock_guard lock(m_mutex);
    if (m_total == 0)
        return std::nullopt;
    return m_perField;
}

std::optional<model::Sample> SampleStore::latest() const
{
    std::lock_guard lock(m_mutex);
    if (m_total == 0)
        return std::nullopt;
    return m_ring[(m_total - 1) % m_capacity];
}

std::vector<model::Sample> SampleStore::since(uint64_t fromSeq, size_t maxCount, uint64_t *nextSeq) const
{
    std::lock_guard lock(m_mutex);
    if (nextSeq)
        *nextSeq = m_total;
    const uint64_t oldest = m_total - m_ring.size();
    uint64_t from = std::max(fromSeq, oldest);
    if (m_total > from && m_total - from > maxCount)
        from = m_total - maxCount;
    std::vector<model::Sample> out;
    out.reserve(size_t(m_total > from ? m_total - from : 0));
    for (uint64_t seq = from; seq < m_total; ++seq)
        out.push_back(m_ring[seq % m_capacity]);
    return out;
}

} // namespace imudesk::device
