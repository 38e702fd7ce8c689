#pragma once
// Choosing a URFR mounting (v1.7.1 §4.6.7.6): by code, or by where the IMU's X and Y axes
// point on the body (right / forward / up are the body's X, Y, Z); the IMU's Z axis
// follows as X x Y, so only right-handed mountings can be chosen. The description of a
// code is the manual's table row ("IMU X right, IMU Y forward, IMU Z up").
#include "model/mounting.h"

#include <QCoreApplication>
#include <QString>

#include <array>
#include <optional>

namespace imudesk::settings {

class MountingChoice {
    Q_DECLARE_TR_FUNCTIONS(MountingChoice)

public:
    // Directions on the body (user frame = body: X right, Y forward, Z up).
    enum class Direction { Right, Left, Forward, Back, Up, Down };
    struct Axes {
        Direction x, y, z; // where IMU X, Y and Z point
    };

    // Where the IMU axes point for a code (the columns of Mounting::userFromSensor).
    static Axes axesOfCode(int code);
    // The code for IMU X and Y directions; std::nullopt and *error when X and Y are
    // parallel. With z given, it must equal X x Y (else refused as left-handed).
    static std::optional<int> codeFor(Direction x, Direction y, std::optional<Direction> z = std::nullopt,
                                      QString *error = nullptr);
    // The unit vector of a direction in the body frame.
    static std::array<int, 3> vector(Direction d);
    static std::optional<Direction> directionOf(const std::array<int, 3> &v);
    static QString directionName(Direction d);   // translated: "right", ...
    static const char *directionKey(Direction d); // "right", "left", "forward", "back", "up", "down"
    static std::optional<Direction> parseDirection(const QString &text);
    // "IMU X right, IMU Y forward, IMU Z up"
    static QString description(int code);
    // The v1.6.6 command form of a code: the nine numbers of C (Mounting::legacyMatrixForCode).
    static QString legacyMatrixText(int code);
};

} // namespace imudesk::settings
