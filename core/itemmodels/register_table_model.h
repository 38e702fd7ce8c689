#pragma once
// A Modbus register map as a table (the register browser): one row per register of the map,
// columns Address / Name / Type / Access / Raw / Value / Unit / Description. Raw and scaled
// values come from register blocks read off the device (setBlock); a cell not read yet shows
// "—". The Raw cell of a writable register is editable: setData checks the value against the
// register's rule and emits writeRequested(address, value); the model never writes itself.
#include "protocol/modbus/register_block.h"
#include "protocol/modbus/register_map.h"

#include <QAbstractTableModel>
#include <QList>

#include <map>

namespace imudesk::models {

class RegisterTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column : int { AddressColumn, NameColumn, TypeColumn, AccessColumn, RawColumn, ValueColumn, UnitColumn,
                        DescriptionColumn, ColumnCount };
    struct Range {
        int start = 0;
        int count = 0;
        friend bool operator==(const Range &, const Range &) = default;
    };

    explicit RegisterTableModel(QObject *parent = nullptr);

    // Shows a map (HiPNUC of one edition or HEC495); clears the values.
    void setMap(const protocol::modbus::RegisterMap &map);
    const protocol::modbus::RegisterMap *map() const { return m_map; }
    // Registers read from the device; rows whose words are all in the block update.
    void setBlock(const protocol::modbus::RegisterBlock &block);
    void clearValues();
    // The reads that cover every readable register (runs of registers at most maxGap apart,
    // each at most 125 long), in address order.
    QList<Range> readRanges(int maxGap = 6) const;
    const protocol::modbus::RegisterDef *registerAt(int row) const;

    int rowCount(const QModelIndex &parent = QModelIndex()) const override;
    int columnCount(const QModelIndex &parent = QModelIndex()) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;

Q_SIGNALS:
    void writeRequested(int address, int value);
    // setData refused a value (what and why).
    void writeRefused(const QString &message);

private:
    const protocol::modbus::RegisterMap *m_map = nullptr;
    std::map<uint16_t, uint16_t> m_words; // register address -> last value read
};

} // namespace imudesk::models
