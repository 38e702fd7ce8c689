#include "local_gravity.h"

#include <cmath>

namespace imudesk::verify {

double normalGravity(double latitudeDeg, double heightM)
{
    // WGS 84 defining and derived constants.
    constexpr double a = 6378137.0;               // semi-major axis (m)
    constexpr double f = 1.0 / 298.257223563;     // flattening
    constexpr double gammaE = 9.7803253359;       // normal gravity at the equator (m/s²)
    constexpr double k = 0.00193185265241;        // Somigliana's constant
    constexpr double e2 = 0.00669437999013;       // first eccentricity squared
    constexpr double m = 0.00344978650684;        // omega² a² b / GM
    const double s = std::sin(latitudeDeg * 3.141592653589793 / 180.0);
    const double s2 = s * s;
    const double gamma = gammaE * (1.0 + k * s2) / std::sqrt(1.0 - e2 * s2);
    const double h = heightM;
    return gamma * (1.0 - 2.0 / a * (1.0 + f + m - 2.0 * f * s2) * h + 3.0 / (a * a) * h * h);
}

} // namespace imudesk::verify
