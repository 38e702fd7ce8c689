#pragma once
// The commands the GUI itself sent to a device, one row each: time, command, status
// (OK / ERR / timeout / ...) and the reply lines joined. record() adds a row when the
// command is queued, complete() fills in its outcome when the reply (or the timeout)
// comes. Bounded to kMaxRows (oldest dropped). QtCore only: colours come from the view.
#include "device/text_reply.h"

#include <QAbstractTableModel>
#include <QDateTime>
#include <QList>
#include <QString>

#include <deque>

namespace imudesk::models {

class CommandLogModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column : int { TimeColumn, CommandColumn, StatusColumn, ReplyColumn, ColumnCount };
    enum Role : int {
        StatusRole = Qt::UserRole + 1, // int(device::TextReply::Status)
        IdRole,                        // quint64 session command id
    };
    static constexpr int kMaxRows = 2000;
    using Status = device::TextReply::Status;

    explicit CommandLogModel(QObject *parent = nullptr);

    // A command the GUI sent, under the session's id (status Pending until complete()).
    void record(quint64 id, const QString &text, const QDateTime &when = QDateTime::currentDateTime());
    // The outcome of command `id`; false when it was not recorded here (or dropped).
    bool complete(quint64 id, const device::TextReply &reply);
    void clear();
    // After a language change: the headers and status words are shown anew.
    void retranslate();

    int rowCount(const QModelIndex &parent = QModelIndex()) const override;
    int columnCount(const QModelIndex &parent = QModelIndex()) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    // Rows as text: one line each, the columns separated by tabs (header line first when
    // asked), for the clipboard and spreadsheets. Rows are taken in ascending order.
    QString rowsAsText(QList<int> rows, bool withHeader = false) const;
    QString allAsText(bool withHeader = false) const;

    // "OK", "ERR", "timeout", ... as the Status column shows it.
    static QString statusText(Status status);
    // The reply lines joined with " | "; for a failure, its reason after them.
    static QString replyText(const device::TextReply &reply);

private:
    struct Row {
        quint64 id = 0;
        QDateTime time;
        QString command;
        Status status = Status::Pending;
        QString reply;
    };
    QString cellText(const Row &row, int column) const;
    int rowOf(quint64 id) const;

    std::deque<Row> m_rows;
};

} // namespace imudesk::models
