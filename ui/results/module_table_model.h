#pragma once
// The Modules tab's table (issue 38): the modules a search of the results database found,
// newest first, one row each: when it started (local time), serial number, outcome in words and
// colour, plan, station, fixture slot, product, firmware and attempt. Texts of any length are
// cut for the cell (ResultsFormat::shortText) and whole in the tooltip.
#include "core/results/result_record.h"

#include <QAbstractTableModel>

#include <vector>

namespace imudesk::ui {

class ModuleTableModel : public QAbstractTableModel {
    Q_OBJECT

public:
    enum Column { Started, Serial, Outcome, Plan, Station, Slot, Product, Firmware, Attempt, ColumnCount };
    // The whole serial number (the history's key), the module's UUID.
    static constexpr int SerialRole = Qt::UserRole + 1;
    static constexpr int UuidRole = Qt::UserRole + 2;

    explicit ModuleTableModel(QObject *parent = nullptr);

    void setModules(std::vector<results::ModuleRecord> modules);
    const std::vector<results::ModuleRecord> &modules() const { return m_modules; }
    const results::ModuleRecord *module(int row) const;
    // The row of the module with that UUID; -1 when it is not shown.
    int rowOf(const QString &uuid) const;
    // The language changed: the headers and the outcomes' words are asked for again.
    void retranslate();

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    // The firmware as found, and what it became when the plan updated it ("1.6.6 → 1.7.1").
    static QString firmwareText(const results::ModuleRecord &m);

private:
    QString fullText(const results::ModuleRecord &m, int column) const;

    std::vector<results::ModuleRecord> m_modules;
};

} // namespace imudesk::ui
