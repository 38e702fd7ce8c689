#pragma once
// Bounded ring of the latest samples, shared between the session's worker thread
// (writer, one lock per batch) and views (readers, on their refresh clock).
#include "model/sample.h"

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace imudesk::device {

class SampleStore {
public:
    explicit SampleStore(size_t capacity = 100000);

    void append(const std::vector<model::Sample> &batch);
    void clear();

    // Total samples ever appended (also the sequence number of the next one).
    uint64_t totalAppended() const;
    size_t size() const;
    size_t capacity() const { return m_capacity; }
    std::optional<model::Sample> latest() const;
    // The latest value of every field any sample carried (model::mergeFields), with the newest
    // sample's source: what a values table shows when frames carry different fields.
    std::optional<model::Sample> latestPerField() const;
    // Seconds since the newest sample that carried each field arrived (index n = bit n of
    // model::SampleField; 0 for a field no sample carried), on the steady clock the sessions
    // stamp hostTimeNs with: a view marks values that stopped arriving.
    using FieldAges = std::array<double, 32>;
    FieldAges fieldAges() const;
    // Samples with sequence >= fromSeq still in the ring (at most maxCount, newest kept).
    // nextSeq, when given, receives the sequence number to ask for next time.
    std::vector<model::Sample> since(uint64_t fromSeq, size_t maxCount = SIZE_MAX, uint64_t *nextSeq = nullptr) const;

private:
    const size_t m_capacity;
    mutable std::mutex m_mutex;
    std::vector<model::Sample> m_ring;
    uint64_t m_total = 0;
    model::Sample m_perField;
    std::array<int64_t, 32> m_fieldTimes{}; // hostTimeNs of each field's newest sample
};

// A reader in another thread that takes every sample once, in order, from the moment it was made
// (or skipToNow()), and counts the samples the ring overwrote before it read them: the live
// bridge and a live MCAP recording of several devices.
class SampleCursor {
public:
    explicit SampleCursor(std::shared_ptr<SampleStore> store)
        : m_store(std::move(store)), m_next(m_store->totalAppended())
    {
    }
    // What arrived since the last take; the samples lost to the ring before it are added to *missed.
    std::vector<model::Sample> take(uint64_t *missed = nullptr)
    {
        uint64_t next = m_next;
        std::vector<model::Sample> batch = m_store->since(m_next, SIZE_MAX, &next);
        if (missed && next - m_next > batch.size())
            *missed += next - m_next - batch.size();
        m_next = next;
        return batch;
    }
    void skipToNow() { m_next = m_store->totalAppended(); }
    const SampleStore *store() const { return m_store.get(); }

private:
    std::shared_ptr<SampleStore> m_store;
    uint64_t m_next;
};

} // namespace imudesk::device
