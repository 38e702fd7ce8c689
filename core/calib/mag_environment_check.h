#pragma once
// The environment checks of the manual's troubleshooting flow (v1.7.1 chapter 9.31):
//   step 1: |B| at the calibration spot must be 20..60 uT;
//   step 3: |B| measured in different orientations at the same spot must not vary by
//           more than 10 uT, else there is spatial interference (move, or use 6-axis mode).
// Feed it calibrated field vectors (the module's mag output after calibration, or ours).
#include <Eigen/Core>

#include <QCoreApplication>
#include <QString>

namespace imudesk::calib {

class MagEnvironmentCheck {
    Q_DECLARE_TR_FUNCTIONS(MagEnvironmentCheck)

public:
    enum class Status { NotEnoughData, Ok, FieldOutOfRange, SpatialInterference };
    struct Options {
        double minFieldUt = 20.0;
        double maxFieldUt = 60.0;
        double maxSpreadUt = 10.0;
        int minSamples = 10;
    };

    MagEnvironmentCheck();
    explicit MagEnvironmentCheck(Options options);

    void reset();
    void add(const Eigen::Vector3d &fieldUt);

    int count() const { return m_count; }
    double meanFieldUt() const { return m_count ? m_sum / m_count : 0.0; }
    double minFieldUt() const { return m_min; }
    double maxFieldUt() const { return m_max; }
    double spreadUt() const { return m_count ? m_max - m_min : 0.0; }
    bool fieldInRange() const;
    bool interference() const { return m_count >= m_options.minSamples && spreadUt() > m_options.maxSpreadUt; }
    // FieldOutOfRange takes precedence over SpatialInterference.
    Status status() const;
    // What to do, from chapter 9.31 (translated).
    QString advice() const;

private:
    Options m_options;
    int m_count = 0;
    double m_sum = 0, m_min = 0, m_max = 0;
};

} // namespace imudesk::calib
