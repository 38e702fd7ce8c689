#include "reply.h"

#include "bcd.h"
#include "commands.h"
#include "model/attitude.h"

#include <cstring>

namespace imudesk::protocol::witlink {

namespace {

uint8_t requestOf(uint8_t reply)
{
    switch (reply) {
    case 0x14: return 0x14;
    case 0x1F: return 0x1F;
    case 0x49: return 0x49;
    case kReplyCalibrationPoint:
    case kReplyCalibrationPointAlt: return 0x67;
    case kReplyStopCalibration: return 0x12;
    case kReplyCalibrationStarted: return 0x08;
    default: break;
    }
    const uint8_t r = reply & 0x7F;
    return (reply & 0x80) && commands::isKnownCommand(r) ? r : 0;
}

bool isStatusReply(uint8_t cmd)
{
    switch (cmd) {
    case 0x86: case 0x88: case 0xE0: case 0xE3: case 0xE4: case 0xE5: case 0x72: case 0x92: case 0x90:
    case 0x8B: case 0x8C: case 0x49: case 0xC9: case 0x8F: case 0x8A: case 0x8E:
        return true;
    default:
        return false;
    }
}

} // namespace

Reply decodeReply(const Frame &f)
{
    Reply r;
    r.address = f.address;
    r.command = f.command;
    r.request = requestOf(f.command);
    const auto &d = f.data;
    auto fail = [&](Reply::Error e) {
        r.error = e;
        r.success = false;
        return r;
    };
    switch (f.command) {
    case 0x81: case 0x82: case 0x83: {
        r.kind = Reply::Kind::Angle;
        if (d.size() != 3)
            return fail(Reply::Error::BadLength);
        const auto a = decodeAngle(d.data());
        if (!a)
            return fail(Reply::Error::BadBcd);
        r.angle = *a;
        r.success = true;
        return r;
    }
    case 0x84: {
        r.kind = Reply::Kind::Angles;
        if (d.size() != 9)
            return fail(Reply::Error::BadLength);
        const auto p = decodeAngle(d.data()), ro = decodeAngle(d.data() + 3), h = decodeAngle(d.data() + 6);
        if (!p || !ro || !h)
            return fail(Reply::Error::BadBcd);
        r.pitch = *p;
        r.roll = *ro;
        r.heading = *h;
        r.success = true;
        return r;
    }
    case 0x14: {
        r.kind = Reply::Kind::AllData;
        const auto rec = AllDataRecord::decode(d.data(), d.size());
        if (!rec)
            return fail(Reply::Error::BadLength);
        r.record = *rec;
        r.success = true;
        return r;
    }
    case 0x87: {
        r.kind = Reply::Kind::Declination;
        if (d.size() != 2)
            return fail(Reply::Error::BadLength);
        const auto v = decodeDeclination(d.data());
        if (!v)
            return fail(Reply::Error::BadBcd);
        r.declination = *v;
        r.success = true;
        return r;
    }
    case 0x89:
        if (d.size() == 5) {
            r.kind = Reply::Kind::CalibrationSaved;
            std::memcpy(&r.fitError, d.data(), 4); // little-endian float (2.9: 00 00 80 3F = 1.0)
            r.points = d[4];
            r.success = true;
            return r;
        }
        r.kind = Reply::Kind::Status;
        if (d.size() != 1)
            return fail(Reply::Error::BadLength);
        if (d[0] != 0xFF)
            return fail(Reply::Error::BadStatus);
        r.success = false;
        return r;
    case kReplyCalibrationPoint:
    case kReplyCalibrationPointAlt:
        r.kind = Reply::Kind::CalibrationPoint;
        if (d.size() != 16)
            return fail(Reply::Error::BadLength);
        std::memcpy(r.pointBytes.data(), d.data(), 15);
        r.points = d[15];
        r.success = true;
        return r;
    case 0x1F:
    case 0x9F:
        r.kind = Reply::Kind::Address;
        if (d.size() != 1)
            return fail(Reply::Error::BadLength);
        r.deviceAddress = d[0];
        r.success = true;
        return r;
    default:
        break;
    }
    if (isStatusReply(f.command)) {
        r.kind = Reply::Kind::Status;
        if (d.size() != 1)
            return fail(Reply::Error::BadLength);
        if (d[0] != 0x00 && d[0] != 0xFF)
            return fail(Reply::Error::BadStatus);
        r.success = d[0] == 0x00;
        return r;
    }
    return fail(Reply::Error::UnknownCommand);
}

QString Reply::errorText(Error e)
{
    switch (e) {
    case Error::None: return tr("no error");
    case Error::UnknownCommand: return tr("a reply command that the HEC495 manual does not list");
    case Error::BadLength: return tr("a data field of the wrong length for this reply");
    case Error::BadBcd: return tr("a BCD value with a digit above 9 or a bad sign nibble");
    case Error::BadStatus: return tr("a status byte that is neither 00 (success) nor FF (failure)");
    }
    return {};
}

QString Reply::describe() const
{
    const QString what = QString::fromLatin1(commands::commandName(request));
    if (!ok())
        return tr("%1: invalid reply (%2)").arg(what, errorText(error));
    switch (kind) {
    case Kind::Angle: return tr("%1: %2 deg").arg(what).arg(angle, 0, 'f', 2);
    case Kind::Angles:
        return tr("pitch %1 deg, roll %2 deg, heading %3 deg")
            .arg(pitch, 0, 'f', 2)
            .arg(roll, 0, 'f', 2)
            .arg(heading, 0, 'f', 2);
    case Kind::AllData:
        return tr("pitch %1 deg, roll %2 deg, heading %3 deg, time %4 ms")
            .arg(double(record.pitch), 0, 'f', 2)
            .arg(double(record.roll), 0, 'f', 2)
            .arg(double(record.heading), 0, 'f', 2)
            .arg(record.timeMs);
    case Kind::Declination: return tr("declination %1 deg").arg(declination, 0, 'f', 1);
    case Kind::Status: return success ? tr("%1: success").arg(what) : tr("%1: the device reported failure").arg(what);
    case Kind::CalibrationSaved:
        return tr("calibration saved: fit error %1, %2 points").arg(double(fitError), 0, 'g', 4).arg(points);
    case Kind::CalibrationPoint: return tr("calibration point collected: %1 points").arg(points);
    case Kind::Address: return tr("address %1").arg(deviceAddress);
    case Kind::Unknown: break;
    }
    return tr("unknown reply");
}

Frame statusReply(uint8_t address, uint8_t command, bool success)
{
    return Frame{address, command, {uint8_t(success ? 0x00 : 0xFF)}};
}

Frame angleReply(uint8_t address, uint8_t command, double deg)
{
    const auto a = encodeAngle(deg).value_or(std::array<uint8_t, 3>{});
    return Frame{address, command, {a[0], a[1], a[2]}};
}

Frame anglesReply(uint8_t address, double pitch, double roll, double heading)
{
    Frame f{address, 0x84, {}};
    for (double v : {pitch, roll, heading}) {
        const auto a = encodeAngle(v).value_or(std::array<uint8_t, 3>{});
        f.data.insert(f.data.end(), a.begin(), a.end());
    }
    return f;
}

Frame calibrationSavedReply(uint8_t address, float fitError, uint8_t points)
{
    Frame f{address, 0x89, std::vector<uint8_t>(5)};
    std::memcpy(f.data.data(), &fitError, 4);
    f.data[4] = points;
    return f;
}

Frame calibrationPointReply(uint8_t address, const std::array<uint8_t, 15> &bytes, uint8_t points)
{
    Frame f{address, kReplyCalibrationPoint, std::vector<uint8_t>(bytes.begin(), bytes.end())};
    f.data.push_back(points);
    return f;
}

std::optional<model::Sample> sampleOf(const Reply &reply, int64_t hostTimeNs)
{
    if (!reply.ok())
        return std::nullopt;
    if (reply.kind == Reply::Kind::AllData)
        return reply.record.toSample(hostTimeNs);
    if (reply.kind != Reply::Kind::Angles)
        return std::nullopt;
    model::Sample s;
    s.source = "HEC495";
    s.hostTimeNs = hostTimeNs;
    s.fields = model::FieldEuler;
    s.pitch = reply.pitch;
    s.roll = reply.roll;
    // One convention for every device: the heading clockwise from magnetic north as its own
    // quantity (the angles reply counts it 0..360, manual 2.4: 313.71; the full record ±180),
    // and the world frame's yaw (ENU, counter-clockwise) as for a HiPNUC module.
    model::setCompassHeading(s, reply.heading, false);
    return s;
}

} // namespace imudesk::protocol::witlink
