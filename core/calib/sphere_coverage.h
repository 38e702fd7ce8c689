#pragma once
// Coverage of field directions on an 80-cell geodesic grid (an icosahedron with every face
// split in four, as ArduPilot's AP_GeodesicGrid; calibration-notes.md §1.3, §8). A
// direction falls in the cell whose centre is nearest. Also the hint of which rotation is
// still missing: the mean direction of the empty cells, in the sensor frame.
#include <Eigen/Core>

#include <QCoreApplication>
#include <QString>

#include <array>
#include <vector>

namespace imudesk::calib {

class SphereCoverage {
    Q_DECLARE_TR_FUNCTIONS(SphereCoverage)

public:
    static constexpr int kCells = 80;
    struct Cell {
        Eigen::Vector3d centre;                // unit vector
        std::array<Eigen::Vector3d, 3> corner; // unit vectors
    };
    static const std::array<Cell, kCells> &cells();
    // Index of the cell holding direction d (need not be normalised); -1 for a zero vector.
    static int cellOf(const Eigen::Vector3d &d);

    void clear();
    // Adds one direction; returns true when it covered a new cell.
    bool add(const Eigen::Vector3d &direction);
    void addAll(const std::vector<Eigen::Vector3d> &directions);
    int count(int cell) const { return m_counts[size_t(cell)]; }
    int coveredCells() const { return m_covered; }
    double percent() const { return 100.0 * m_covered / kCells; }
    bool covered(int cell) const { return m_counts[size_t(cell)] > 0; }
    // Unit vector towards the empty cells (zero when everything is covered or nothing is).
    Eigen::Vector3d missingDirection() const;
    // The radius of the largest hole, in degrees: over the empty cells, the largest angle from
    // one to its nearest covered cell (0 when every cell is covered, 180 when none is). One
    // missing cell gives about 25 degrees; an uncovered hemisphere about 90.
    double largestGapDeg() const;
    // What the user should do next, e.g. "Turn the module so that its -Z axis points along
    // the field (north and down)"; empty when the sphere is covered.
    QString missingRotationHint() const;

private:
    std::array<int, kCells> m_counts{};
    int m_covered = 0;
};

} // namespace imudesk::calib
