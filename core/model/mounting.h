#pragma once
// Mounting (URFR): the v1.7.1 three-digit code "ABC" (each digit 0..5 = +X,-X,+Y,-Y,+Z,-Z
// names the sensor direction of the user X, Y and Z axis; 24 right-handed codes) and
// the v1.6.6 nine-number matrix C (row-major C00..C22; as the manual's named examples
// print it, X_U = C * X_B: see legacyMatrixForCode).
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace imudesk::model {

using Matrix3 = std::array<std::array<double, 3>, 3>;

class Mounting {
public:
    static constexpr int kDefaultCode = 24; // 024: X right, Y forward, Z up

    // All 24 legal codes in the manual's table order (ascending).
    static const std::vector<int> &validCodes();
    static bool isValidCode(int code);
    // Parses "24", "024", "531"; nullopt when not one of the 24 codes.
    static std::optional<int> parseCode(const std::string &text);
    // The 3-digit form used on the wire ("24" for 024: the manual shows two digits).
    static std::string codeText(int code);

    // R such that v_user = R * v_sensor (row i = sensor direction of user axis i).
    static Matrix3 userFromSensor(int code);
    // The v1.6.6 URFR matrix C for a code: userFromSensor, as the manual's named mountings print it.
    static Matrix3 legacyMatrixForCode(int code);
    // The code whose matrix equals m (to 1e-6), if any.
    static std::optional<int> codeForLegacyMatrix(const Matrix3 &m);
    // True when m is a proper rotation (orthonormal, det +1) to the given tolerance.
    static bool isRotation(const Matrix3 &m, double tol = 1e-3);

    static Matrix3 identity();
};

} // namespace imudesk::model
