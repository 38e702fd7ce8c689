#pragma once
// The latest Sample as a table: one row per quantity, columns Quantity / Value /
// Unit. Views call refresh() on their clock (never per sample); only cells whose
// text changed emit dataChanged. A field the sample does not carry shows "—".
#include "model/device_identity.h"
#include "model/display_units.h"
#include "model/sample.h"

#include <QAbstractTableModel>
#include <QString>

#include <array>
#include <optional>

namespace imudesk::models {

class LatestValuesModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Row : int {
        AccX,
        AccY,
        AccZ,
        GyrX,
        GyrY,
        GyrZ,
        MagX,
        MagY,
        MagZ,
        Roll,
        Pitch,
        Yaw,
        QuatW,
        QuatX,
        QuatY,
        QuatZ,
        Pressure,
        Temperature,
        MagRelX, // a compass's relative magnetic field (HEC495, serial and CAN)
        MagRelY,
        MagRelZ,
        MagRoll, // the HEC495's magnetic tool face
        DeviceTime,
        // Fields only some frame types carry (HI81/HI83 INS, HI92/HI83 ship motion, HI50 inclinometer);
        // their rows are offered once a frame carried them (everSeen()).
        InsStatus,
        Latitude,
        Longitude,
        Altitude,
        VelEast,
        VelNorth,
        VelUp,
        GnssFix,
        UtcTime,
        Heave,
        Surge,
        Sway,
        InclinationX,
        InclinationY,
        Heading,         // NMEA HDT / HDM (a compass's NMEA output)
        // HI83 fields beyond the ones above, one row per data_bitmap bit (v1.7.1 manual 5.9.12).
        UtcDate,         // bit 6
        HeaveSurgeSwayFreq, // bit 11
        AccEnu,          // bit 13
        GnssHeadingFix,  // bit 15: solq_heading, nv_heading
        OdometerSpeed,   // bit 16
        Undulation,      // bit 17
        DiffAge,         // bit 18
        NodeId,          // bit 19
        EventCounters,   // bit 25
        KfAccBias,       // bit 26
        KfGyrBias,       // bit 27
        GnssAccuracy,    // bit 28
        DualAntenna,     // bit 29
        GnssPosition,    // bit 30
        GnssVelocity,    // bit 31
        StatusFlags,
        FrameType,
        RowCount
    };
    enum Column : int { QuantityColumn, ValueColumn, UnitColumn, ColumnCount };
    // data(): true for a row whose value stopped arriving (views grey it out).
    static constexpr int StaleRole = Qt::UserRole + 1;
    // A value that has not arrived for this long is stale: shown with its age.
    static constexpr double kStaleAfterS = 2.0;
    // Seconds since each field last arrived (device::SampleStore::fieldAges); a field at 0 or
    // below counts as fresh.
    using FieldAges = std::array<double, 32>;

    // Shown for a quantity the latest sample does not carry.
    static QString missingText();

    explicit LatestValuesModel(QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = QModelIndex()) const override;
    int columnCount(const QModelIndex &parent = QModelIndex()) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    // Shows `sample` (or "—" everywhere when empty); emits dataChanged only for changed cells.
    // `ages` marks the values that stopped arriving (an HEC495 that streams angles after its
    // full records: acceleration and rate keep their last value, greyed, with their age).
    void refresh(const std::optional<model::Sample> &sample, const FieldAges &ages = {});
    bool isStale(Row row) const { return m_staleSeconds[size_t(row)] > 0; }
    // The text of a stale value: the value and its age (views size their columns with it).
    static QString staleText(const QString &value, int ageSeconds);
    // Texts are translated when read; call after the application language changed.
    void retranslate();
    // Units for acceleration and angular rate (values and the unit column follow).
    void setUnits(const model::DisplayUnits &units);
    const model::DisplayUnits &units() const { return m_units; }
    // The frame of the module's attitude (identity.worldFrame): the angle and quaternion rows
    // say "NWU" for a module set to CONFIG IMU COORD 4.
    void setWorldFrame(model::WorldFrame frame);
    model::WorldFrame worldFrame() const { return m_worldFrame; }

    QString valueText(Row row) const { return m_values[size_t(row)]; }
    // True once any sample shown carried this row's field (the frame type row: any sample).
    bool everSeen(Row row) const;
    // True for the rows that always show (the IMU and attitude quantities every frame type has).
    static bool isCoreRow(Row row) { return (row < InsStatus && (row < MagRelX || row > MagRoll)) || row >= StatusFlags; }
    // The HI83 fields only an INS configuration sends (UtcDate ... GnssVelocity): the workspace
    // shows them in a table of their own, so that the values table keeps every row in view.
    static bool isDetailRow(Row row) { return row >= UtcDate && row <= GnssVelocity; }
    // Ship motion and inclination: beside those details they move to the details table too.
    static bool isSecondaryRow(Row row) { return row >= Heave && row <= InclinationY; }

private:
    QString formatValue(Row row, const model::Sample &s) const;
    QString quantityName(Row row) const;
    QString unitName(Row row) const;
    QString toolTip(Row row) const;

    QString shownValue(Row row) const;

    std::array<QString, RowCount> m_values;
    std::array<int, RowCount> m_staleSeconds{}; // whole seconds since the value arrived, 0 = fresh
    std::optional<model::Sample> m_last;
    uint32_t m_seenFields = 0;
    uint32_t m_seenHi83Bits = 0;
    model::DisplayUnits m_units;
    model::WorldFrame m_worldFrame = model::WorldFrame::Enu;
};

} // namespace imudesk::models
