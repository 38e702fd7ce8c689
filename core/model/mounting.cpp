#include "mounting.h"

#include <cmath>
#include <cstdio>

namespace imudesk::model {
namespace {

std::array<int, 3> axis(int digit)
{
    std::array<int, 3> v{0, 0, 0};
    v[size_t(digit / 2)] = (digit % 2) ? -1 : 1;
    return v;
}

std::array<int, 3> cross(const std::array<int, 3> &a, const std::array<int, 3> &b)
{
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

std::vector<int> enumerate()
{
    std::vector<int> codes;
    for (int a = 0; a < 6; ++a)
        for (int b = 0; b < 6; ++b)
            for (int c = 0; c < 6; ++c)
                if (cross(axis(a), axis(b)) == axis(c))
                    codes.push_back(a * 100 + b * 10 + c);
    return codes;
}

} // namespace

const std::vector<int> &Mounting::validCodes()
{
    static const std::vector<int> codes = enumerate();
    return codes;
}

bool Mounting::isValidCode(int code)
{
    for (int c : validCodes())
        if (c == code)
            return true;
    return false;
}

std::optional<int> Mounting::parseCode(const std::string &text)
{
    if (text.empty() || text.size() > 3)
        return std::nullopt;
    int v = 0;
    for (char ch : text) {
        if (ch < '0' || ch > '5')
            return std::nullopt;
        v = v * 10 + (ch - '0');
    }
    if (!isValidCode(v))
        return std::nullopt;
    return v;
}

std::string Mounting::codeText(int code)
{
    return std::to_string(code);
}

Matrix3 Mounting::userFromSensor(int code)
{
    Matrix3 r{};
    const int digits[3] = {code / 100, (code / 10) % 10, code % 10};
    for (int i = 0; i < 3; ++i) {
        const auto a = axis(digits[i]);
        for (int j = 0; j < 3; ++j)
            r[size_t(i)][size_t(j)] = a[size_t(j)];
    }
    return r;
}

// The v1.6.6 manual (2.2.4 CONFIG, "座標系旋轉(改變安裝方式)") defines X_B = C * X_U, but
// every one of its named examples prints the other matrix: "Y軸正方向朝下的垂直安裝" is
// 1 0 0 / 0 0 1 / 0 -1 0 (also its worked example), "Y軸正方向朝上" 1 0 0 / 0 0 -1 / 0 1 0,
// "X軸正方向朝上" 0 0 -1 / 0 1 0 / 1 0 0, "X軸正方向朝下" 0 0 1 / 0 1 0 / -1 0 0. The same names
// are the v1.6.6 Modbus URFR values (4.2, register 0xA6: 1 = Y down, 2 = Y up, 3 = X up,
// 4 = X down) and the v1.7.1 codes (4.6.7.6: 043 "IMU Y 指下", 052 "IMU Y 指上", 520 "IMU X
// 指上", 421 "IMU X 指下"). ImuDesk follows the names, so a mounting chosen by name is the
// same over ASCII and over Modbus: C is the code's user-from-sensor matrix (X_U = C * X_B).
Matrix3 Mounting::legacyMatrixForCode(int code)
{
    return userFromSensor(code);
}

std::optional<int> Mounting::codeForLegacyMatrix(const Matrix3 &m)
{
    for (int code : validCodes()) {
        const Matrix3 c = legacyMatrixForCode(code);
        bool same = true;
        for (size_t i = 0; i < 3 && same; ++i)
            for (size_t j = 0; j < 3 && same; ++j)
                same = std::fabs(c[i][j] - m[i][j]) < 1e-6;
        if (same)
            return code;
    }
    return std::nullopt;
}

bool Mounting::isRotation(const Matrix3 &m, double tol)
{
    for (size_t i = 0; i < 3; ++i)
        for (size_t j = 0; j < 3; ++j) {
            double dot = 0;
            for (size_t k = 0; k < 3; ++k)
                dot += m[i][k] * m[j][k];
            if (std::fabs(dot - (i == j ? 1.0 : 0.0)) > tol)
                return false;
        }
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    return std::fabs(det - 1.0) < tol;
}

Matrix3 Mounting::identity()
{
    return {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
}

} // namespace imudesk::model
