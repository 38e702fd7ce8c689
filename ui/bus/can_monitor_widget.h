#pragma once
// The CAN frame monitor dock's content, in the manner of PCAN-View: a table with one row per
// identifier (count, cycle time, last data, decoded meaning), a filter, pause, clear, CSV
// export, and a line to send an arbitrary frame. Self-contained: feed it
// CanSession::framesSeen and connect sendFrameRequested to CanSession::sendFrame.
#include "device/can_session_types.h"
#include "itemmodels/can_frame_monitor_model.h"

#include <QWidget>

#include <optional>

QT_BEGIN_NAMESPACE
class QCheckBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableView;
class QToolButton;
QT_END_NAMESPACE

namespace imudesk::ui {

class CanMonitorWidget : public QWidget {
    Q_OBJECT
public:
    explicit CanMonitorWidget(QWidget *parent = nullptr);

    models::CanFrameMonitorModel *model() { return m_model; }
    QTableView *table() { return m_table; }

    void addEvents(const imudesk::device::CanFrameEvents &events);
    // Exports to path; returns false and shows why in the status line.
    bool exportCsv(const QString &path);
    // Parses the send line ("18FF3408" / "608", data "2B 00 18 05 0A 00 00 00"); nullopt + reason when bad.
    static std::optional<protocol::can::CanFrame> parseFrame(const QString &id, const QString &data, bool extended, bool fd,
                                                             QString *error);

Q_SIGNALS:
    void sendFrameRequested(const imudesk::protocol::can::CanFrame &frame);

private:
    void onSend();
    void onExport();
    void updateStatus();

    models::CanFrameMonitorModel *m_model;
    QTableView *m_table;
    QLineEdit *m_filter;
    QToolButton *m_pause;
    QPushButton *m_clear;
    QPushButton *m_export;
    QLineEdit *m_sendId;
    QLineEdit *m_sendData;
    QCheckBox *m_sendExt;
    QCheckBox *m_sendFd;
    QPushButton *m_send;
    QLabel *m_status;
};

} // namespace imudesk::ui
