#include "latest_values_model.h"

#include <cmath>

#include "model/main_status.h"
#include "plot/channel_catalog.h"

#include <QStringList>

namespace imudesk::models {

namespace {

using model::Sample;
using model::SampleField;
using Row = LatestValuesModel::Row;

// The first rows are the chartable channels, in plot::Channel order (the catalogue names them).
static_assert(int(Row::Temperature) + 1 == plot::kChannelCount && int(Row::AccX) == int(plot::Channel::AccX));
bool isChannel(Row row)
{
    return int(row) < plot::kChannelCount;
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
    default: break; // the channel rows (above), the frame type
    }
    return 0;
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
    case Qt::ToolTipRole: return toolTip(row);
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
    return (m_seenFields & fieldOf(row)) != 0;
}

void LatestValuesModel::refresh(const std::optional<model::Sample> &sample)
{
    m_last = sample;
    if (sample)
        m_seenFields |= sample->fields | (sample->source.empty() ? 0u : 1u << 31);
    int firstChanged = -1;
    auto flush = [this, &firstChanged](int lastRow) {
        if (firstChanged < 0)
            return;
        Q_EMIT dataChanged(index(firstChanged, ValueColumn), index(lastRow, ValueColumn), {Qt::DisplayRole});
        firstChanged = -1;
    };
    for (int r = 0; r < RowCount; ++r) {
        const auto row = Row(r);
        QString text = sample ? formatValue(row, *sample) : missingText();
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
        m_values[size_t(r)] = m_last ? formatValue(Row(r), *m_last) : missingText();
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
        case plot::ChannelGroup::Magnetometer: return fixed(v, 3);
        case plot::ChannelGroup::Euler: return fixed(v, 2);
        case plot::ChannelGroup::Quaternion: return fixed(v, 4);
        case plot::ChannelGroup::Pressure:
        case plot::ChannelGroup::Temperature: return fixed(v, 1);
        }
    }
    switch (row) {
    case DeviceTime: return fixed(s.deviceTimeMs, 0);
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
        const int whole = int(s.utcTimeOfDayS);
        return QStringLiteral("%1:%2:%3")
            .arg(whole / 3600, 2, 10, QLatin1Char('0'))
            .arg(whole / 60 % 60, 2, 10, QLatin1Char('0'))
            .arg(s.utcTimeOfDayS - whole / 60 * 60, 5, 'f', 2, QLatin1Char('0'));
    }
    case Heave: return fixed(s.heaveSurgeSway.x, 2);
    case Surge: return fixed(s.heaveSurgeSway.y, 2);
    case Sway: return fixed(s.heaveSurgeSway.z, 2);
    case InclinationX: return fixed(s.inclinationX, 3);
    case InclinationY: return fixed(s.inclinationY, 3);
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
    default: break; // the channel rows (above)
    }
    return missingText();
}

QString LatestValuesModel::quantityName(Row row) const
{
    if (isChannel(row))
        return plot::channelName(plot::Channel(row));
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
    case StatusFlags: return tr("Status flags");
    case FrameType: return tr("Frame type");
    default: break; // the channel rows (above)
    }
    return {};
}

QString LatestValuesModel::unitName(Row row) const
{
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
    case Roll: return tr("Roll angle, in degrees (Euler angles in the device's convention, ENU 312 by default).");
    case Pitch: return tr("Pitch angle, in degrees (Euler angles in the device's convention, ENU 312 by default).");
    case Yaw:
        return tr("Yaw (heading) angle, in degrees (Euler angles in the device's convention, ENU 312 by default).");
    case QuatW:
    case QuatX:
    case QuatY:
    case QuatZ:
        return tr("Attitude quaternion, component %1 (body to navigation frame), no unit.").arg(axisName(row));
    case Pressure: return tr("Air pressure from the barometer, in Pa.");
    case Temperature: return tr("Sensor temperature, in °C.");
    case DeviceTime:
        return tr("Device timestamp in ms: UTC time of day when synchronised, otherwise time since power-up.");
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
    case RowCount: break;
    }
    return {};
}

} // namespace imudesk::models
