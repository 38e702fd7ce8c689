#pragma once
// CAN traffic in the manner of PCAN-View: one row per identifier (and direction) with the
// frame type, DLC, last data, cycle time, count and the decoded meaning. Feed it batches of
// frame events (CanSession::framesSeen); views need no clock of their own because a batch
// updates each changed row once. Filter (identifier or meaning text), pause, clear, CSV export.
// Bounded: at most maxRows() identifiers; frames of further identifiers are only counted.
#include "device/can_session_types.h"
#include "protocol/can/can_decoder.h"

#include <QAbstractTableModel>
#include <QString>

#include <unordered_map>
#include <vector>

QT_BEGIN_NAMESPACE
class QIODevice;
QT_END_NAMESPACE

namespace imudesk::models {

class CanFrameMonitorModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column : int { ColId, ColType, ColDlc, ColData, ColPeriod, ColCount, ColMeaning, ColumnCount };
    // Raw values for sorting and tests.
    enum Role : int { IdRole = Qt::UserRole + 1, CountRole, PeriodMsRole, TransmittedRole };

    static constexpr int kDefaultMaxRows = 2048;

    explicit CanFrameMonitorModel(QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    void addEvents(const device::CanFrameEvents &events);
    void clear();

    void setPaused(bool paused) { m_paused = paused; }
    bool isPaused() const { return m_paused; }
    // Case-insensitive: a row is shown when its identifier text or its meaning contains it.
    void setFilter(const QString &text);
    QString filter() const { return m_filter; }
    void setProtocol(protocol::can::CanProtocol p) { m_decoder.setProtocol(p); }
    void setMaxRows(int n) { m_maxRows = n > 0 ? n : 1; }
    int maxRows() const { return m_maxRows; }

    uint64_t totalFrames() const { return m_total; }
    uint64_t framesWhilePaused() const { return m_whilePaused; }
    uint64_t framesOverLimit() const { return m_overLimit; }

    // Every row (filtered or not) as CSV: id,type,direction,dlc,data,period_ms,count,meaning.
    bool exportCsv(QIODevice *out) const;
    bool exportCsv(const QString &path, QString *error) const;

private:
    struct Row {
        protocol::can::CanFrame frame;
        bool tx = false;
        uint64_t count = 0;
        qint64 lastNs = 0;
        double periodMs = 0; // smoothed cycle time
        QString meaning;
    };
    static uint64_t keyOf(const protocol::can::CanFrame &f, bool tx);
    bool matches(const Row &r) const;
    QString typeText(const Row &r) const;
    void rebuildVisible();

    std::vector<Row> m_rows;
    std::unordered_map<uint64_t, size_t> m_index; // key -> m_rows index
    std::vector<int> m_visible;                   // visible row -> m_rows index
    std::vector<int> m_visibleOf;                 // m_rows index -> visible row or -1
    protocol::can::CanDecoder m_decoder;
    QString m_filter;
    bool m_paused = false;
    int m_maxRows = kDefaultMaxRows;
    uint64_t m_total = 0, m_whilePaused = 0, m_overLimit = 0;
};

} // namespace imudesk::models
