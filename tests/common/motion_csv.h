#pragma once
// Vendor HI91 CSV files of a module at rest or moved (issue 53: Allan deviation needs a still
// recording), for the analysis's tests: 100 Hz, the given seconds, deterministic noise.
#include "protocol/hipnuc/payloads.h"
#include "decode/hipnuc_vendor_csv.h"

#include <QFile>
#include <QString>

#include <cmath>
#include <random>
#include <string>

namespace motion_csv {

enum class Motion {
    Still,      // a good gyro at rest: 0.02 deg/s of noise
    NoisyStill, // at rest, 0.4 deg/s of noise (the simulator's noisy-gyro)
    ByHand,     // turned back and forth by hand: a gyro std dev of about 147 deg/s
    SlowTurn,   // at rest but for a 3 deg/s turn about z from 20 s to 30 s
    Tilted,     // at rest, tilted by 15 deg at 30 s
};

constexpr double kPi = 3.14159265358979323846;

inline bool write(const QString &path, Motion motion, double seconds = 60, uint32_t seed = 5)
{
    namespace hp = imudesk::protocol::hipnuc;
    std::mt19937 rng(seed);
    std::normal_distribution<double> n;
    const double gyroNoise = motion == Motion::NoisyStill ? 0.4 : 0.02;
    std::string text = imudesk::decode::vendor_csv::hi91Header();
    text += '\n';
    const int rows = int(seconds * 100);
    for (int i = 0; i < rows; ++i) {
        const double t = i / 100.0;
        double gx = 0.1, gy = -0.05, gz = 0.02, tilt = 0;
        if (motion == Motion::ByHand) {
            gx += 208 * std::sin(2 * kPi * 0.7 * t);
            gy += 208 * std::sin(2 * kPi * 0.45 * t + 1);
            gz += 208 * std::sin(2 * kPi * 0.9 * t + 2);
            tilt = 0.5 * std::sin(2 * kPi * 0.7 * t);
        } else if (motion == Motion::SlowTurn && t >= 20 && t < 30) {
            gz += 3;
        } else if (motion == Motion::Tilted && t >= 30) {
            tilt = 15 * kPi / 180;
        }
        hp::Hi91 h;
        h.temperature = 25;
        h.pressure = 101325;
        h.systemTime = uint32_t(1000 + 10 * i);
        h.gyr = {float(gx + gyroNoise * n(rng)), float(gy + gyroNoise * n(rng)), float(gz + gyroNoise * n(rng))};
        h.acc = {float(std::sin(tilt) + 0.001 * n(rng)), float(0.001 * n(rng)), float(std::cos(tilt) + 0.001 * n(rng))};
        h.mag = {20, -5, 40};
        imudesk::decode::vendor_csv::appendRow(text, h, 10.0 * i);
    }
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(text.data(), qint64(text.size())) == qint64(text.size());
}

} // namespace motion_csv
