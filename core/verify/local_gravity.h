#pragma once
// The bench's gravity: the magnitude every still pose's specific force must have (verify's
// multi-position accelerometer fit). A module divides m/s² by the vendor's G of 9.8
// (model::kGravity), so the magnitude it should read is localGravity / 9.8 — not 1: between
// the equator and the poles gravity differs by 0.5 %, which a fit against 1 G would report as
// the accelerometer's scale error.
//
// Normal gravity on the WGS 84 ellipsoid (Somigliana's closed form) with the second-order
// height correction (NIMA TR8350.2, eq. 4-1 and 4-3): good to about 1e-4 m/s² (0.001 %) of
// the real value near the surface, well inside what verify's scale figures need; local
// anomalies (mountains, ores) reach 3e-3 m/s² (0.03 %).
namespace imudesk::verify {

inline constexpr double kStandardGravity = 9.80665; // m/s²
// The spread of gravity over the inhabited Earth about the standard value (m/s², 1 sigma):
// what verify carries as the uncertainty of a gravity it had to assume.
inline constexpr double kAssumedGravitySigma = 0.014;

// m/s² at a geodetic latitude (deg, -90..90) and a height above the ellipsoid (m).
double normalGravity(double latitudeDeg, double heightM);

} // namespace imudesk::verify
