#include "replay_group.h"

#include "record/replay_session.h"

#include <algorithm>

namespace imudesk::record {

void ReplayGroup::add(ReplaySession *member)
{
    if (std::find(m_members.begin(), m_members.end(), member) == m_members.end())
        m_members.push_back(member);
}

void ReplayGroup::remove(ReplaySession *member)
{
    m_members.erase(std::remove(m_members.begin(), m_members.end(), member), m_members.end());
}

void ReplayGroup::play()
{
    for (ReplaySession *m : m_members)
        m->playAlone();
}

void ReplayGroup::pause()
{
    for (ReplaySession *m : m_members)
        m->pauseAlone();
}

void ReplayGroup::seek(double seconds)
{
    for (ReplaySession *m : m_members)
        m->seekAlone(seconds);
}

void ReplayGroup::setSpeed(double factor)
{
    const double f = factor <= 0 ? ReplaySession::kMaxSpeed : factor;
    for (ReplaySession *m : m_members)
        m->setSpeedAlone(f);
}

void ReplayGroup::setLoop(bool on)
{
    for (ReplaySession *m : m_members)
        m->setLoopAlone(on);
}

} // namespace imudesk::record
