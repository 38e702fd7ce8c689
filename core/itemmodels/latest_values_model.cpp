#include "latest_values_model.h"

#include <bit>
#include <cmath>

#include "format/time_text.h"
#include "model/main_status.h"
#include "plot/channel_catalog.h"

#include <QStringList>

namespace imudesk::models {

namespace {

using model::Sample;
using model::SampleField;
using Row = LatestValuesModel::Row;

// The first rows are the chartable channels, in plot::Channel order (the catalogue names them).
static_assert(int(Row::MagRoll) + 1 == plot::kChannelCount && int(Row::AccX) == int(plot::Channel::AccX)
              && int(Row::MagRelX) == int(plot::Channel::MagRelX));
bool isChannel(Row row)
{
    return int(row) < plot::kChannelCount;
}

// The HI83 data_bitmap bit of a row that shows Sample::hi83, -1 for the other rows.
int hi83BitOf(Row row)
{
    switch (row) {
    case Row::UtcDate: return 6;
    case Row::HeaveSurgeSwayFreq: return 11;
    case Row::AccEnu: return 13;
    case Row::GnssHeadingFix: return 15;
    case Row::OdometerSpeed: return 16;
    case Row::Undulation: return 17;
    case Row::DiffAge: return 18;
    case Row::NodeId: return 19;
    case Row::EventCounters: return 25;
    case Row::KfAccBias: return 26;
    case Row::KfGyrBias: return 27;
    case Row::GnssAccuracy: return 28;
    case Row::DualAntenna: return 29;
    case Row::GnssPosition: return 30;
    case Row::GnssVelocity: return 31;
    default: return -1;
    }
}

// The Sample field a row needs, 0 when the row needs none.
uint32_t fieldOf(Row row)
{
    if (isChannel(row))
        return plot::channelInfo(plot::Channel(row)).field;
    switch (row) {
    case Row::DeviceTime: return model::FieldDeviceTime;
    case Row::InsStatus: return model::FieldInsStatus;
    case Row::Latitude:
    case Row::Longitude:
    case Row::Altitude: return model::FieldPosition;
    case Row::VelEast:
    case Row::VelNorth:
    case Row::VelUp: return model::FieldVelocity;
    case Row::GnssFix:
    case Row::UtcTime: return model::FieldGnss;
    case Row::Heave:
    case Row::Surge:
    case Row::Sway: return model::FieldHeave;
    case Row::InclinationX:
    case Row::InclinationY: return model::FieldInclination;
    case Row::StatusFlags: return model::FieldMainStatus;
    case Row::Heading: return model::FieldHeading;
    default: break; // the channel rows (above), the frame type
    }
    return hi83BitOf(row) >= 0 ? uint32_t(model::FieldHi83Extra) : 0u;
}

// Fixed-point text without a "-0.000" that would flicker around zero.
QString fixed(double v, int decimals)
{
    QString s = QString::number(v, 'f', decimals);
    if (s.startsWith(QLatin1Char('-'))) {
        bool allZero = true;
        for (qsizetype i = 1; i < s.size() && allZero; ++i)
            allZero = s.at(i) == QLatin1Char('0') || s.at(i) == QLatin1Char('.');
        if (allZero)
            s.remove(0, 1);
    }
    return s;
}

// Three components in one cell, the order the tooltip names.
template <typename T> QString triple(const std::array<T, 3> &v, int decimals)
{
    return QStringLiteral("%1  %2  %3").arg(fixed(v[0], decimals), fixed(v[1], decimals), fixed(v[2], decimals));
}

// True when the sample's device time is the ms of the UTC day: an HI91 whose status word
// (firmware 1.7.0 and later; the workspace drops it for older firmware) has UTC_UNSYNC clear.
bool utcClock(const model::Sample &s)
{
    return s.source == "HI91" && s.has(model::FieldDeviceTime) && s.has(model::FieldMainStatus)
        && !model::MainStatus(s.mainStatus).test(model::MainStatus::UtcUnsync);
}

QString axisName(Row row)
{
    return isChannel(row) ? QLatin1String(plot::channelInfo(plot::Channel(row)).axis) : QString();
}

} // namespace

QString LatestValuesModel::missingText()
{
    return QStringLiteral("\u2014");
}

LatestValuesModel::LatestValuesModel(QObject *parent) : QAbstractTableModel(parent)
{
    m_values.fill(missingText());
}

int LatestValuesModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(RowCount);
}

int LatestValuesModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(ColumnCount);
}

QVariant LatestValuesModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const auto row = Row(index.row());
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case QuantityColumn: return quantityName(row);
        case ValueColumn: return m_values[size_t(row)];
        case UnitColumn: return unitName(row);
        default: return {};
        }
    case Qt::ToolTipRole:
        if (isStale(row) && index.column() == ValueColumn)
            return tr("No new value for %n s: the device stopped sending this quantity (another output "
                      "content, a polled record that stopped, or a link that went quiet).",
                      nullptr, m_staleSeconds[size_t(row)]);
        return toolTip(row);
    case StaleRole: return isStale(row);
    case Qt::TextAlignmentRole:
        if (index.column() == ValueColumn)
            return QVariant(Qt::AlignRight | Qt::AlignVCenter);
        return QVariant(Qt::AlignLeft | Qt::AlignVCenter);
    default: return {};
    }
}

QVariant LatestValuesModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (role == Qt::TextAlignmentRole && orientation == Qt::Horizontal)
        return QVariant((section == ValueColumn ? Qt::AlignRight : Qt::AlignLeft) | Qt::AlignVCenter);
    if (role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    if (orientation == Qt::Vertical)
        return section + 1;
    switch (section) {
    case QuantityColumn: return tr("Quantity");
    case ValueColumn: return tr("Value");
    case UnitColumn: return tr("Unit");
    default: return {};
    }
}

bool LatestValuesModel::everSeen(Row row) const
{
    if (row == FrameType)
        return m_seenFields != 0;
    if (const int bit = hi83BitOf(row); bit >= 0)
        return (m_seenHi83Bits >> bit) & 1u;
    return (m_seenFields & fieldOf(row)) != 0;
}

QString LatestValuesModel::staleText(const QString &value, int ageSeconds)
{
    if (ageSeconds < 100)
        return tr("%1 (%2 s old)", "a value that stopped arriving, with its age").arg(value).arg(ageSeconds);
    return tr("%1 (%2 min old)", "a value that stopped arriving, with its age").arg(value).arg(ageSeconds / 60);
}

QString LatestValuesModel::shownValue(Row row) const
{
    QString text = m_last ? formatValue(row, *m_last) : missingText();
    if (const int age = m_staleSeconds[size_t(row)]; age > 0)
        text = staleText(text, age);
    return text;
}

void LatestValuesModel::refresh(const std::optional<model::Sample> &sample, const FieldAges &ages)
{
    const bool wasUtc = m_last && utcClock(*m_last);
    m_last = sample;
    if (wasUtc != (sample && utcClock(*sample))) // the device time's unit: ms or UTC
        Q_EMIT dataChanged(index(DeviceTime, UnitColumn), index(DeviceTime, UnitColumn), {Qt::DisplayRole});
    if (sample) {
        m_seenFields |= sample->fields | (sample->source.empty() ? 0u : 1u << 31);
        if (sample->hi83)
            m_seenHi83Bits |= sample->hi83->bits;
    }
    int firstChanged = -1;
    auto flush = [this, &firstChanged](int lastRow) {
        if (firstChanged < 0)
            return;
        Q_EMIT dataChanged(index(firstChanged, ValueColumn), index(lastRow, ValueColumn),
                           {Qt::DisplayRole, Qt::ToolTipRole, StaleRole});
        firstChanged = -1;
    };
    for (int r = 0; r < RowCount; ++r) {
        const auto row = Row(r);
        const uint32_t field = fieldOf(row);
        const double age = sample && field && sample->has(model::SampleField(field))
                               ? ages[size_t(std::countr_zero(field))]
                               : 0.0;
        m_staleSeconds[size_t(r)] = age >= kStaleAfterS ? int(age) : 0;
        QString text = shownValue(row);
        if (text == m_values[size_t(r)]) {
            flush(r - 1);
            continue;
        }
        m_values[size_t(r)] = std::move(text);
        if (firstChanged < 0)
            firstChanged = r;
    }
    flush(RowCount - 1);
}

void LatestValuesModel::retranslate()
{
    for (int r = 0; r < RowCount; ++r)
        m_values[size_t(r)] = shownValue(Row(r));
    Q_EMIT headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
    Q_EMIT dataChanged(index(0, 0), index(RowCount - 1, ColumnCount - 1), {Qt::DisplayRole, Qt::ToolTipRole});
}

void LatestValuesModel::setUnits(const model::DisplayUnits &units)
{
    if (units == m_units)
        return;
    m_units = units;
    retranslate(); // every value and unit text again
}

void LatestValuesModel::setWorldFrame(model::WorldFrame frame)
{
    if (frame == m_worldFrame)
        return;
    m_worldFrame = frame;
    retranslate();
}

QString LatestValuesModel::formatValue(Row row, const model::Sample &s) const
{
    if (row == FrameType)
        return s.source.empty() ? missingText() : QString::fromStdString(s.source);
    if (!(s.fields & fieldOf(row)))
        return missingText();
    if (isChannel(row)) {
        const plot::ChannelInfo &i = plot::channelInfo(plot::Channel(row));
        const double v = i.read(s);
        switch (i.group) {
        case plot::ChannelGroup::Accelerometer: return fixed(v * m_units.accelFactor(), 4);
        case plot::ChannelGroup::Gyroscope:
            return fixed(v * m_units.rateFactor(), m_units.rate == model::RateUnit::RadiansPerSecond ? 5 : 3);
        case plot::ChannelGroup::Magnetometer:
        case plot::ChannelGroup::MagneticRelative: return fixed(v, 3);
        case plot::ChannelGroup::Euler: return fixed(v, row == MagRoll ? 1 : 2);
        case plot::ChannelGroup::Quaternion: return fixed(v, 4);
        case plot::ChannelGroup::Pressure:
        case plot::ChannelGroup::Temperature: return fixed(v, 1);
        }
    }
    switch (row) {
    case DeviceTime:
        if (utcClock(s)) // HI91 system_time aligned to the UTC day by PPS (v1.7.1 manual 2.2.2)
            return format::timeOfDayText(double(int64_t(s.deviceTimeMs) % 86400000) / 1000.0, 3);
        return fixed(s.deviceTimeMs, 0);
    case InsStatus: {
        switch (s.insStatus) {
        case 0: return tr("0 invalid");
        case 1: return tr("1 aligning");
        case 3: return tr("3 navigating");
        case 6: return tr("6 dead reckoning");
        default: return QString::number(s.insStatus);
        }
    }
    case Latitude: return fixed(s.latitudeDeg, 7);
    case Longitude: return fixed(s.longitudeDeg, 7);
    case Altitude: return std::isnan(s.altitudeM) ? missingText() : fixed(s.altitudeM, 3);
    case VelEast: return fixed(s.velEnu.x, 2);
    case VelNorth: return fixed(s.velEnu.y, 2);
    case VelUp: return fixed(s.velEnu.z, 2);
    case GnssFix: {
        if (s.gnssQuality < 0)
            return missingText();
        QString fix;
        switch (s.gnssQuality) {
        case 0: fix = tr("0 no fix"); break;
        case 1: fix = tr("1 single"); break;
        case 2: fix = tr("2 DGNSS"); break;
        case 4: fix = tr("4 RTK fixed"); break;
        case 5: fix = tr("5 RTK float"); break;
        default: fix = QString::number(s.gnssQuality); break;
        }
        // The satellites in brackets (the tooltip says so): the value column stays narrow.
        return s.gnssSatellites < 0 ? fix : QStringLiteral("%1 (%2)").arg(fix).arg(s.gnssSatellites);
    }
    case UtcTime: {
        if (s.utcTimeOfDayS < 0)
            return missingText();
        return format::timeOfDayText(s.utcTimeOfDayS, 2);
    }
    case Heave: return fixed(s.heaveSurgeSway.x, 2);
    case Surge: return fixed(s.heaveSurgeSway.y, 2);
    case Sway: return fixed(s.heaveSurgeSway.z, 2);
    case InclinationX: return fixed(s.inclinationX, 3);
    case InclinationY: return fixed(s.inclinationY, 3);
    case Heading: return QStringLiteral("%1 %2").arg(fixed(s.headingDeg, 1), s.headingTrue ? tr("true") : tr("magnetic"));
    case StatusFlags: {
        const model::MainStatus status(s.mainStatus);
        QStringList names;
        for (const auto &n : status.setFlagNames())
            names << QString::fromStdString(n);
        const QString hex =
            QLatin1String("0x") + QString::number(s.mainStatus, 16).toUpper().rightJustified(4, QLatin1Char('0'));
        if (names.isEmpty())
            return tr("none (%1)").arg(hex);
        return QStringLiteral("%1 (%2)").arg(names.join(QLatin1Char(' ')), hex);
    }
    default: break; // the channel rows (above), HI83 (below)
    }
    if (const int bit = hi83BitOf(row); bit >= 0) {
        if (!s.hi83 || !s.hi83->has(bit))
            return missingText();
        const model::Hi83Extra &x = *s.hi83;
        switch (row) {
        case UtcDate:
            return QStringLiteral("%1-%2-%3")
                .arg(x.utcDate[0], 4, 10, QLatin1Char('0'))
                .arg(x.utcDate[1], 2, 10, QLatin1Char('0'))
                .arg(x.utcDate[2], 2, 10, QLatin1Char('0'));
        case HeaveSurgeSwayFreq: return triple(x.hssFreqHz, 2);
        case AccEnu: return triple(x.accEnu, 3);
        case GnssHeadingFix: return QStringLiteral("%1 (%2)").arg(x.solqHeading).arg(x.nvHeading);
        case OdometerSpeed: return fixed(x.odSpeedMs, 2);
        case Undulation: return fixed(x.undulationM, 2);
        case DiffAge: return fixed(x.diffAgeS, 1);
        case NodeId: return QString::number(x.nodeId);
        case EventCounters: {
            // The named counters that have counted (gravity, mag, gnss_pos, ...); all of them in the tooltip.
            static const char *const names[] = {"grav", "mag", "pos", "vel", "dual", "nhc", "zupt", "zaru", "zihr", "od"};
            QStringList parts;
            for (size_t i = 0; i < x.eventCounter.size(); ++i)
                if (x.eventCounter[i] != 0)
                    parts << QStringLiteral("%1 %2")
                                 .arg(i < std::size(names) ? QLatin1String(names[i]) : QString::number(i))
                                 .arg(x.eventCounter[i]);
            return parts.isEmpty() ? QStringLiteral("0") : parts.join(QLatin1Char(' '));
        }
        case KfAccBias: return triple(x.kfAccBias, 4);
        case KfGyrBias: return triple(x.kfGyrBias, 5);
        case GnssAccuracy: return QStringLiteral("%1  %2").arg(fixed(x.gnssStd[0], 2), fixed(x.gnssStd[1], 2));
        case DualAntenna: return triple(x.dualHeading, 2);
        case GnssPosition:
            return QStringLiteral("%1  %2  %3")
                .arg(fixed(x.gnssLonLatMsl[1], 7), fixed(x.gnssLonLatMsl[0], 7), fixed(x.gnssLonLatMsl[2], 2));
        case GnssVelocity: return triple(x.gnssVelEnu, 2);
        default: break;
        }
    }
    return missingText();
}

QString LatestValuesModel::quantityName(Row row) const
{
    if (isChannel(row)) {
        const QString name = plot::channelName(plot::Channel(row));
        // A module set to NWU reports its attitude in that frame: its rows say so.
        if (m_worldFrame == model::WorldFrame::Nwu && row >= Roll && row <= QuatZ)
            return tr("%1 (NWU)", "an attitude quantity of a module set to North-West-Up").arg(name);
        return name;
    }
    switch (row) {
    case DeviceTime: return tr("Device time");
    case InsStatus: return tr("INS status");
    case Latitude: return tr("Latitude");
    case Longitude: return tr("Longitude");
    case Altitude: return tr("Altitude (MSL)");
    case VelEast: return tr("Velocity east");
    case VelNorth: return tr("Velocity north");
    case VelUp: return tr("Velocity up");
    case GnssFix: return tr("GNSS fix");
    case UtcTime: return tr("UTC time");
    case Heave: return tr("Heave");
    case Surge: return tr("Surge");
    case Sway: return tr("Sway");
    case InclinationX: return tr("Inclination X");
    case InclinationY: return tr("Inclination Y");
    case Heading: return tr("Heading");
    case UtcDate: return tr("UTC date");
    case HeaveSurgeSwayFreq: return tr("Heave/surge/sway frequency");
    case AccEnu: return tr("Acceleration E N U");
    case GnssHeadingFix: return tr("GNSS heading fix");
    case OdometerSpeed: return tr("Odometer speed");
    case Undulation: return tr("Geoid undulation");
    case DiffAge: return tr("Differential age");
    case NodeId: return tr("Node ID");
    case EventCounters: return tr("Filter updates");
    case KfAccBias: return tr("KF accelerometer bias");
    case KfGyrBias: return tr("KF gyroscope bias");
    case GnssAccuracy: return tr("GNSS std position, velocity");
    case DualAntenna: return tr("Dual antenna");
    case GnssPosition: return tr("GNSS lat lon alt");
    case GnssVelocity: return tr("GNSS velocity E N U");
    case StatusFlags: return tr("Status flags");
    case FrameType: return tr("Frame type");
    default: break; // the channel rows (above)
    }
    return {};
}

QString LatestValuesModel::unitName(Row row) const
{
    if (row == DeviceTime && m_last && utcClock(*m_last))
        return tr("UTC");
    switch (fieldOf(row)) {
    case model::FieldAcc: return m_units.accel == model::AccelUnit::G ? tr("G") : tr("m/s²");
    case model::FieldGyr: return m_units.rate == model::RateUnit::DegreesPerSecond ? tr("deg/s") : tr("rad/s");
    case model::FieldMag: return tr("µT");
    case model::FieldEuler: return tr("deg");
    case model::FieldPressure: return tr("Pa");
    case model::FieldTemperature: return tr("°C");
    case model::FieldDeviceTime: return tr("ms");
    case model::FieldPosition: return row == Altitude ? tr("m") : tr("deg");
    case model::FieldVelocity: return tr("m/s");
    case model::FieldHeave: return tr("m");
    case model::FieldInclination: return tr("deg");
    case model::FieldHeading: return tr("deg");
    case model::FieldMagRelative: return tr("relative");
    case model::FieldMagRoll: return tr("deg");
    default: break;
    }
    switch (row) {
    case HeaveSurgeSwayFreq: return tr("Hz");
    case AccEnu:
    case KfAccBias: return tr("m/s²");
    case KfGyrBias: return tr("rad/s");
    case OdometerSpeed:
    case GnssVelocity: return tr("m/s");
    case Undulation: return tr("m");
    case DiffAge: return tr("s");
    case GnssAccuracy: return tr("m, m/s");
    case DualAntenna: return tr("m, deg, deg");
    case GnssPosition: return tr("deg, deg, m");
    default: return QString();
    }
}

QString LatestValuesModel::toolTip(Row row) const
{
    switch (row) {
    case AccX:
    case AccY:
    case AccZ:
        return tr("Acceleration along the sensor's %1 axis, in G (1 G = 9.8 m/s², the vendor's constant).")
            .arg(axisName(row));
    case GyrX:
    case GyrY:
    case GyrZ: return tr("Angular velocity about the sensor's %1 axis, in deg/s.").arg(axisName(row));
    case MagX:
    case MagY:
    case MagZ: return tr("Magnetic field along the sensor's %1 axis, in µT.").arg(axisName(row));
    case Roll:
    case Pitch:
    case Yaw:
        if (m_worldFrame == model::WorldFrame::Nwu)
            return tr("%1 angle, in degrees: Euler angles 3-1-2 in the North-West-Up frame the module is set to "
                      "(CONFIG IMU COORD 4); the yaw is 0 with the module's Y axis pointing west.")
                .arg(row == Roll ? tr("Roll") : row == Pitch ? tr("Pitch") : tr("Yaw"));
        if (row == Pitch)
            return tr("Pitch angle, in degrees (Euler angles in the device's convention, ENU 312 by default).");
        if (row == Yaw)
            return tr("Yaw (heading) angle, in degrees (Euler angles in the device's convention, ENU 312 by "
                      "default).");
        return tr("Roll angle, in degrees (Euler angles in the device's convention, ENU 312 by default).");
    case QuatW:
    case QuatX:
    case QuatY:
    case QuatZ:
        return m_worldFrame == model::WorldFrame::Nwu
            ? tr("Attitude quaternion, component %1 (body to the North-West-Up frame the module is set to), no unit.")
                  .arg(axisName(row))
            : tr("Attitude quaternion, component %1 (body to navigation frame), no unit.").arg(axisName(row));
    case Pressure: return tr("Air pressure from the barometer, in Pa.");
    case Temperature: return tr("Sensor temperature, in °C.");
    case DeviceTime:
        return tr("Device timestamp: the UTC time of day once a PPS input has aligned the module's clock (HI91, "
                  "UTC_UNSYNC clear), otherwise ms since power-up.");
    case InsStatus: return tr("Integrated navigation state: 0 invalid, 1 aligning, 3 navigating, 6 dead reckoning.");
    case Latitude:
    case Longitude: return tr("Position from integrated navigation, in degrees (south and west negative).");
    case Altitude: return tr("Height above mean sea level, in m.");
    case VelEast:
    case VelNorth:
    case VelUp: return tr("Velocity in the east-north-up frame, in m/s.");
    case GnssFix:
        return tr("GNSS fix quality as in NMEA GGA, then in brackets the satellites used, from the latest GGA or SXT "
                  "sentence.");
    case UtcTime: return tr("UTC time of day from the latest NMEA sentence (GGA, RMC or SXT), hh:mm:ss.ss.");
    case Heave:
    case Surge:
    case Sway: return tr("Ship motion displacement (heave, surge, sway), in m.");
    case InclinationX:
    case InclinationY: return tr("Inclinometer angle about the %1 axis, in degrees.").arg(row == InclinationX ? QStringLiteral("X") : QStringLiteral("Y"));
    case StatusFlags:
        return tr("MAIN_STATUS flags set in the latest frame (firmware 1.7.0 and later), then the raw word in hex.");
    case FrameType: return tr("The frame type (packet tag) that carried the latest values, e.g. HI91.");
    case Heading:
        return tr("Heading from the latest NMEA heading sentence, in degrees clockwise from north: HDT true north, "
                  "HDM magnetic north (an HEC495 with output content NMEA 0183 sends HDT).");
    case MagRelX:
    case MagRelY:
    case MagRelZ:
        return tr("The compass's magnetic field along its X, Y and Z axes as a relative value without unit: the "
                  "horizontal component of the field pointing north is 1 (HEC495 manual 2.5, the same on CAN).");
    case MagRoll:
        return tr("Magnetic roll (magnetic tool face), in degrees: the roll from the magnetic field, meaningful when "
                  "the pitch is near ±90° (HEC495 manual 2.5).");
    case UtcDate: return tr("UTC date from the HI83 frame (bit 6), shown once GNSS time is known.");
    case HeaveSurgeSwayFreq: return tr("Ship motion frequency (HI83 bit 11): heave, surge, sway, in Hz.");
    case AccEnu: return tr("Acceleration in the east-north-up frame from integrated navigation (HI83 bit 13): E, N, U, in m/s².");
    case GnssHeadingFix:
        return tr("Heading solution state of the GNSS (HI83 bit 15, solq_heading), then in brackets its satellites.");
    case OdometerSpeed: return tr("Speed from an external odometer (HI83 bit 16), in m/s.");
    case Undulation: return tr("Geoid undulation: height of the geoid above the ellipsoid (HI83 bit 17), in m.");
    case DiffAge: return tr("Age of the RTK differential corrections (HI83 bit 18), in s.");
    case NodeId: return tr("The module's node ID, the same as its CAN ID, 1 to 127 (HI83 bit 19).");
    case EventCounters:
        return tr("Measurement updates the integrated navigation filter has made (HI83 bit 25), the counters that are "
                  "not zero: grav gravity, mag magnetometer, pos GNSS position, vel GNSS velocity, dual dual-antenna "
                  "heading, nhc non-holonomic constraint, zupt zero velocity, zaru zero angular rate, zihr zero "
                  "heading change, od odometer; a number for the reserved counters 10 to 15.");
    case KfAccBias: return tr("Accelerometer bias the navigation filter estimates (HI83 bit 26): X, Y, Z, in m/s².");
    case KfGyrBias: return tr("Gyroscope bias the navigation filter estimates (HI83 bit 27): X, Y, Z, in rad/s.");
    case GnssAccuracy:
        return tr("GNSS accuracy (HI83 bit 28): norm of the position standard deviation in m, of the velocity "
                  "standard deviation in m/s.");
    case DualAntenna:
        return tr("Dual-antenna GNSS heading (HI83 bit 29): baseline length in m, pitch and heading in degrees.");
    case GnssPosition:
        return tr("Raw GNSS position (HI83 bit 30): latitude and longitude in degrees, height above mean sea level "
                  "in m.");
    case GnssVelocity: return tr("Raw GNSS velocity (HI83 bit 31): east, north, up, in m/s.");
    case RowCount: break;
    }
    return {};
}

} // namespace imudesk::models
