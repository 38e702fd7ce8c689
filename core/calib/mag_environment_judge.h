#pragma once
// Judges a calibration spot from the raw, uncalibrated magnetometer while the user turns the
// module, the way the environment can actually show itself. The raw |B| of a module mixes the
// surroundings with the module's own iron (the hard iron shifts every reading by one vector, so
// |B| changes with the orientation): judged raw, a clean spot looks "too strong" or "varying"
// because of exactly what the calibration exists to remove. So the module's iron is fitted out
// first (an ellipsoid once the field has pointed into enough of the sphere, a sphere before)
// and what is left is judged:
//  * the field strength after the fit against the Earth's 20..65 µT (manual v1.7.1 9.31 step 1
//    asks for 20..60 µT at the spot; the Earth's field reaches 65 µT near the poles);
//  * the spread of the fitted field over the orientations, robust to single glitches: a spot
//    whose field is not the same in every orientation (9.31 step 3, more than 10 µT);
//  * |B| while the module is still: the module's iron turns with it, so a change there comes
//    from the surroundings (a magnet or a motor that moves, a current that switches).
// Plain value class, bounded (kMaxSamples orientations), no timers: feed it samples, ask it.
#include "calib/ellipsoid_fit.h"

#include <Eigen/Core>

#include <QCoreApplication>
#include <QString>

#include <deque>
#include <optional>
#include <vector>

namespace imudesk::calib {

class MagEnvironmentJudge {
    Q_DECLARE_TR_FUNCTIONS(MagEnvironmentJudge)

public:
    static constexpr size_t kMaxSamples = 3000; // orientations kept for the fit

    enum class Status {
        TurnMore,            // not enough orientations for a fit yet
        Ok,                  // the spot is fit for calibrating
        FieldOutOfRange,     // the fitted field (ellipsoid) is outside the Earth's range
        SpatialInterference, // the fitted field differs between orientations
        FieldChanging,       // |B| changed while the module was still
    };
    struct Options {
        double minFieldUt = 20.0;
        double maxFieldUt = 65.0;
        double maxSpreadUt = 10.0;     // 5th..95th percentile of the fitted |B|
        double maxStillChangeUt = 3.0; // |B| drift over a still stretch
        double stillGyroDps = 3.0;     // |gyro| below this: still
        double stillMinMs = 1000;      // a still stretch is judged after this long
        double averageMs = 250;        // |B| is averaged over this at each end of a stretch
        double minSeparationDeg = 4.0; // a sample joins the fit when it points this far from the last one kept
        int minCellsForFit = 10;       // of SphereCoverage's 80 cells: a sphere fit
        int minCellsForEllipsoid = 24; // an ellipsoid fit (it also removes the soft iron)
    };

    MagEnvironmentJudge();
    explicit MagEnvironmentJudge(Options options);
    const Options &options() const { return m_options; }

    void reset();
    // One sample: time (ms, increasing), raw field (µT), and the gyro (deg/s) when the module
    // reports it (without it, stillness is not judged).
    void add(double timeMs, const Eigen::Vector3d &rawUt, const std::optional<Eigen::Vector3d> &gyroDps = {});

    int count() const { return m_count; }                            // samples seen
    int orientations() const { return int(m_points.size()); }          // samples kept for the fit
    double rawFieldUt() const { return m_lastRaw; }                    // |B| of the newest sample
    double meanRawFieldUt() const { return m_count ? m_rawSum / m_count : 0.0; }
    int coveredCells() const { return m_covered; }                     // of 80, at the last fit
    double coveragePercent() const { return 100.0 * coveredCells() / 80.0; }

    // After a fit (std::nullopt before): the field without the module's own iron, the size of
    // that iron (|hard iron|), the spread of the fitted |B| and whether the soft iron was
    // fitted too (an ellipsoid) or only the hard iron (a sphere).
    std::optional<double> fittedFieldUt() const;
    std::optional<double> moduleIronUt() const;
    std::optional<double> spreadUt() const;
    bool ellipsoid() const { return m_fit && m_fitIsEllipsoid; }
    // The largest |B| drift over a still stretch so far (0 when none was long enough).
    double stillChangeUt() const { return m_stillChangeMax; }
    bool stillNow() const { return m_stillNow; }

    Status status() const;
    // What it means and what to do (translated).
    QString advice() const;

private:
    void fit();
    void trackStillness(double timeMs, double fieldUt, const std::optional<Eigen::Vector3d> &gyroDps);

    Options m_options;
    int m_count = 0;
    double m_rawSum = 0;
    double m_lastRaw = 0;
    std::vector<Eigen::Vector3d> m_points;
    int m_covered = 0; // SphereCoverage cells around the centre, at the last fit
    int m_keptSinceFit = 0;
    std::optional<Ellipsoid> m_fit;
    bool m_fitIsEllipsoid = false;
    double m_spread = 0;
    // The still stretch in progress: (time, |B|).
    std::deque<std::pair<double, double>> m_still;
    bool m_stillNow = false;
    double m_stillChangeMax = 0;
};

} // namespace imudesk::calib
