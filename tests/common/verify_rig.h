#pragma once
// A module turned by hand through still poses (sim::Motion::Poses), sampled as its sensors and
// its filter would report it, with the truth of every error injected: the module check's
// fixture (tst_module_check, bench_verify). The attitude it reports is the true one, late by
// `lagMs` and off by `attitudeBiasDeg` (roll, pitch, heading clockwise), as HipnucSimulator
// reports it with the faults attitude-bias and filter-lag.
#include "model/attitude.h"
#include "model/sample.h"
#include "sim/motion_model.h"
#include "sim/sensor_model.h"
#include "verify/module_check.h"

#include <array>
#include <cmath>
#include <vector>

namespace imudesk::test {

struct HandTurnedModule {
    uint64_t seed = 1;
    double rateHz = 400;
    double tailS = 3;                                 // still after the last pose
    sim::SensorModel::AccError accError;
    Eigen::Vector3d gyroScale = Eigen::Vector3d::Zero(); // fractions
    Eigen::Vector3d gyroMisalignment = Eigen::Vector3d::Zero(); // rad, as AccError::misalignmentRad
    std::array<double, 3> attitudeBiasDeg{0, 0, 0};
    double lagMs = 0;
    double ironLeft = 0.02; // the magnetometer as a module's MCAL left it
    bool withMag = true;

    std::vector<verify::MotionSample> record() const
    {
        const sim::MotionModel motion(sim::MotionModel::Options{seed, sim::Motion::Poses});
        sim::SensorModel sensors(seed);
        sensors.setAccError(accError);
        sensors.setGyroScaleErrors(gyroScale);
        sensors.setGyroMisalignment(gyroMisalignment);
        sensors.setIronLeft(ironLeft);
        const double end = motion.posesEndS() + tailS;
        std::vector<verify::MotionSample> out;
        out.reserve(size_t(end * rateHz) + 1);
        for (size_t i = 0;; ++i) {
            const double t = double(i) / rateHz;
            if (t > end)
                break;
            const sim::MotionState state = motion.at(t);
            const sim::SensorReading r = sensors.sample(state);
            verify::MotionSample s;
            s.tS = t;
            s.acc = r.acc;
            s.gyr = r.gyr;
            s.mag = r.mag;
            s.hasMag = withMag;
            model::Euler e = sim::eulerEnu312(motion.at(std::max(0.0, t - lagMs * 1e-3)).q);
            e.roll += attitudeBiasDeg[0];
            e.pitch += attitudeBiasDeg[1];
            e.yaw -= attitudeBiasDeg[2];
            s.q = sim::quatFromEnu312(e);
            s.hasAttitude = true;
            out.push_back(s);
        }
        return out;
    }

    // The same as a HiPNUC module's HI91 samples (its own clock, the quaternion it reports).
    std::vector<model::Sample> hi91Samples() const
    {
        std::vector<model::Sample> out;
        for (const verify::MotionSample &m : record()) {
            model::Sample s;
            s.source = "HI91";
            s.deviceTimeMs = m.tS * 1000;
            s.acc = {m.acc.x(), m.acc.y(), m.acc.z()};
            s.gyr = {m.gyr.x(), m.gyr.y(), m.gyr.z()};
            s.mag = {m.mag.x(), m.mag.y(), m.mag.z()};
            s.quat = {m.q.w(), m.q.x(), m.q.y(), m.q.z()};
            s.fields = model::FieldAcc | model::FieldGyr | model::FieldMag | model::FieldQuat | model::FieldDeviceTime;
            out.push_back(s);
        }
        return out;
    }
};

} // namespace imudesk::test
