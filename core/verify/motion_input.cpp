#include "motion_input.h"

#include "model/attitude.h"

namespace imudesk::verify {

double sampleTimeS(const model::Sample &s)
{
    return s.has(model::FieldDeviceTime) ? s.deviceTimeMs * 1e-3 : double(s.hostTimeNs) * 1e-9;
}

bool reportedAttitude(const model::Sample &s, Eigen::Quaterniond &out)
{
    model::Quat q;
    if (s.has(model::FieldQuat) && model::isUsableQuat(s.quat))
        q = model::normalized(s.quat);
    else if (s.has(model::FieldEuler))
        q = model::quatFromEnu312(model::Euler{s.roll, s.pitch, s.yaw});
    else
        return false;
    out = Eigen::Quaterniond(q.w, q.x, q.y, q.z);
    return true;
}

void MotionInput::add(const model::Sample &s)
{
    const bool motion = s.has(model::FieldAcc) && s.has(model::FieldGyr);
    if (m_source.empty()) {
        if (!motion)
            return;
        m_source = s.source;
    }
    if (s.source != m_source)
        return;
    if (!motion || full()) {
        ++m_passedOver;
        return;
    }
    MotionSample m;
    double t = sampleTimeS(s) + m_offsetS;
    if (!m_samples.empty()) {
        const double last = m_samples.back().tS;
        if (t <= last) { // the device restarted or its counter wrapped: carry the time across
            ++m_clockJumps;
            const double step = m_lastDtS > 0 ? m_lastDtS : 1e-3;
            m_offsetS += last + step - t;
            t = last + step;
        }
        m_lastDtS = t - last;
    }
    m.tS = t;
    m.acc = Eigen::Vector3d(s.acc.x, s.acc.y, s.acc.z);
    m.gyr = Eigen::Vector3d(s.gyr.x, s.gyr.y, s.gyr.z);
    if (s.has(model::FieldMag)) {
        m.mag = Eigen::Vector3d(s.mag.x, s.mag.y, s.mag.z);
        m.hasMag = true;
    }
    m.hasAttitude = reportedAttitude(s, m.q);
    m_samples.push_back(m);
}

} // namespace imudesk::verify
