#include "baud_scan.h"

#include <algorithm>
#include <utility>

namespace imudesk::device {

BaudScan::BaudScan(QObject *parent) : QObject(parent)
{
    m_listen.setSingleShot(true);
    connect(&m_listen, &QTimer::timeout, this, [this] {
        const uint64_t generation = m_generation;
        m_plan.probe(m_plan.bauds[m_index], [this, generation](Outcome o) { answered(generation, o); });
    });
}

void BaudScan::start(Plan plan)
{
    stop();
    m_plan = std::move(plan);
    m_running = true;
    tryAt(0);
}

void BaudScan::stop()
{
    m_running = false;
    ++m_generation;
    m_listen.stop();
}

void BaudScan::tryAt(size_t index)
{
    ++m_generation;
    if (index >= m_plan.bauds.size()) {
        m_running = false;
        // A copy: the callback may start the next scan, which replaces m_plan.
        if (const auto exhausted = m_plan.exhausted)
            exhausted();
        return;
    }
    m_index = index;
    if (m_plan.tune)
        m_plan.tune(m_plan.bauds[index]);
    m_listen.start(std::max(0, m_plan.listenMs));
}

void BaudScan::answered(uint64_t generation, Outcome outcome)
{
    if (!m_running || generation != m_generation)
        return;
    switch (outcome) {
    case Outcome::TryNext: tryAt(m_index + 1); return;
    case Outcome::Found:
        m_running = false;
        ++m_generation;
        if (const auto found = m_plan.found)
            found(m_plan.bauds[m_index]);
        return;
    case Outcome::Stop:
        m_running = false;
        ++m_generation;
        if (const auto stopped = m_plan.stopped)
            stopped();
        return;
    }
}

} // namespace imudesk::device
