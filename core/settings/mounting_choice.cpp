#include "mounting_choice.h"

#include "protocol/hipnuc/ascii_command.h"

#include <QStringList>

namespace imudesk::settings {

namespace {
constexpr MountingChoice::Direction kAll[] = {MountingChoice::Direction::Right, MountingChoice::Direction::Left,
                                              MountingChoice::Direction::Forward, MountingChoice::Direction::Back,
                                              MountingChoice::Direction::Up, MountingChoice::Direction::Down};

std::array<int, 3> cross(const std::array<int, 3> &a, const std::array<int, 3> &b)
{
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// The URFR digit of a sensor-frame unit vector (0 +X, 1 -X, 2 +Y, 3 -Y, 4 +Z, 5 -Z).
int digitOf(const std::array<int, 3> &v)
{
    for (int i = 0; i < 3; ++i)
        if (v[size_t(i)] != 0)
            return i * 2 + (v[size_t(i)] < 0 ? 1 : 0);
    return -1;
}
} // namespace

std::array<int, 3> MountingChoice::vector(Direction d)
{
    switch (d) {
    case Direction::Right: return {1, 0, 0};
    case Direction::Left: return {-1, 0, 0};
    case Direction::Forward: return {0, 1, 0};
    case Direction::Back: return {0, -1, 0};
    case Direction::Up: return {0, 0, 1};
    case Direction::Down: return {0, 0, -1};
    }
    return {0, 0, 0};
}

std::optional<MountingChoice::Direction> MountingChoice::directionOf(const std::array<int, 3> &v)
{
    for (Direction d : kAll)
        if (vector(d) == v)
            return d;
    return std::nullopt;
}

MountingChoice::Axes MountingChoice::axesOfCode(int code)
{
    const model::Matrix3 r = model::Mounting::userFromSensor(code);
    Direction out[3] = {Direction::Right, Direction::Forward, Direction::Up};
    for (size_t s = 0; s < 3; ++s) {
        // Sensor axis s in the user (body) frame: column s of R (v_user = R * v_sensor).
        const std::array<int, 3> col = {int(r[0][s]), int(r[1][s]), int(r[2][s])};
        if (const auto d = directionOf(col))
            out[s] = *d;
    }
    return {out[0], out[1], out[2]};
}

std::optional<int> MountingChoice::codeFor(Direction x, Direction y, std::optional<Direction> z, QString *error)
{
    const auto vx = vector(x), vy = vector(y);
    const auto vz = cross(vx, vy);
    if (vz == std::array<int, 3>{0, 0, 0}) {
        if (error)
            *error = tr("IMU X and IMU Y cannot both point %1 / %2: they must be at right angles")
                         .arg(directionName(x), directionName(y));
        return std::nullopt;
    }
    if (z && vector(*z) != vz) {
        if (error)
            *error = tr("IMU X %1, IMU Y %2, IMU Z %3 is left-handed or not at right angles: with X %1 and Y %2, "
                        "Z points %4")
                         .arg(directionName(x), directionName(y), directionName(*z),
                              directionName(*directionOf(vz)));
        return std::nullopt;
    }
    // Row i of R (the sensor direction of user axis i) is (vx[i], vy[i], vz[i]).
    int code = 0;
    for (size_t i = 0; i < 3; ++i)
        code = code * 10 + digitOf({vx[i], vy[i], vz[i]});
    if (!model::Mounting::isValidCode(code)) {
        if (error)
            *error = tr("no URFR code for this mounting");
        return std::nullopt;
    }
    return code;
}

QString MountingChoice::directionName(Direction d)
{
    switch (d) {
    case Direction::Right: return tr("right");
    case Direction::Left: return tr("left");
    case Direction::Forward: return tr("forward");
    case Direction::Back: return tr("back");
    case Direction::Up: return tr("up");
    case Direction::Down: return tr("down");
    }
    return {};
}

const char *MountingChoice::directionKey(Direction d)
{
    switch (d) {
    case Direction::Right: return "right";
    case Direction::Left: return "left";
    case Direction::Forward: return "forward";
    case Direction::Back: return "back";
    case Direction::Up: return "up";
    case Direction::Down: return "down";
    }
    return "";
}

std::optional<MountingChoice::Direction> MountingChoice::parseDirection(const QString &text)
{
    const QString t = text.trimmed().toLower();
    for (Direction d : kAll)
        if (t == QLatin1String(directionKey(d)) || t == directionName(d))
            return d;
    return std::nullopt;
}

QString MountingChoice::description(int code)
{
    const Axes a = axesOfCode(code);
    return tr("IMU X %1, IMU Y %2, IMU Z %3").arg(directionName(a.x), directionName(a.y), directionName(a.z));
}

QString MountingChoice::legacyMatrixText(int code)
{
    const model::Matrix3 c = model::Mounting::legacyMatrixForCode(code);
    QStringList parts;
    for (const auto &row : c)
        for (double v : row)
            parts << QString::fromStdString(protocol::hipnuc::commands::formatNumber(v));
    return parts.join(QLatin1Char(','));
}

} // namespace imudesk::settings
