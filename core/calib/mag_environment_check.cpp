#include "calib/mag_environment_check.h"

#include <algorithm>
#include <cmath>

namespace imudesk::calib {

MagEnvironmentCheck::MagEnvironmentCheck() = default;

MagEnvironmentCheck::MagEnvironmentCheck(Options options)
    : m_options(options)
{
}

void MagEnvironmentCheck::reset()
{
    m_count = 0;
    m_sum = m_min = m_max = 0;
}

void MagEnvironmentCheck::add(const Eigen::Vector3d &fieldUt)
{
    if (!fieldUt.allFinite())
        return;
    const double b = fieldUt.norm();
    if (m_count == 0) {
        m_min = m_max = b;
    } else {
        m_min = std::min(m_min, b);
        m_max = std::max(m_max, b);
    }
    m_sum += b;
    ++m_count;
}

bool MagEnvironmentCheck::fieldInRange() const
{
    const double b = meanFieldUt();
    return b >= m_options.minFieldUt && b <= m_options.maxFieldUt;
}

MagEnvironmentCheck::Status MagEnvironmentCheck::status() const
{
    if (m_count < m_options.minSamples)
        return Status::NotEnoughData;
    if (!fieldInRange())
        return Status::FieldOutOfRange;
    if (interference())
        return Status::SpatialInterference;
    return Status::Ok;
}

QString MagEnvironmentCheck::advice() const
{
    switch (status()) {
    case Status::NotEnoughData:
        return tr("Hold the module at the calibration spot and turn it slowly to a few orientations.");
    case Status::Ok:
        return tr("The field is %1 µT (normal: %2..%3 µT) and varies by %4 µT between orientations: you can "
                  "calibrate here.")
            .arg(meanFieldUt(), 0, 'f', 1)
            .arg(m_options.minFieldUt, 0, 'f', 0)
            .arg(m_options.maxFieldUt, 0, 'f', 0)
            .arg(spreadUt(), 0, 'f', 1);
    case Status::FieldOutOfRange:
        return tr("The field is %1 µT, outside the normal %2..%3 µT: a strongly magnetic object is near. Move away "
                  "from it, or choose another place.")
            .arg(meanFieldUt(), 0, 'f', 1)
            .arg(m_options.minFieldUt, 0, 'f', 0)
            .arg(m_options.maxFieldUt, 0, 'f', 0);
    case Status::SpatialInterference:
        return tr("The field strength varies by %1 µT between orientations (more than %2 µT): there is spatial "
                  "interference here. Choose another place (outdoors, away from buildings and vehicles), or use "
                  "6-axis mode.")
            .arg(spreadUt(), 0, 'f', 1)
            .arg(m_options.maxSpreadUt, 0, 'f', 0);
    }
    return {};
}

} // namespace imudesk::calib
