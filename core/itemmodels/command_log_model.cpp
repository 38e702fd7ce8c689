#include "command_log_model.h"

#include <algorithm>

namespace imudesk::models {

namespace {
QString oneLine(QString text)
{
    // Tabs and line breaks would split the copied row.
    text.replace(QLatin1Char('\t'), QLatin1Char(' '));
    text.replace(QLatin1Char('\r'), QLatin1Char(' '));
    text.replace(QLatin1Char('\n'), QLatin1Char(' '));
    return text;
}
} // namespace

CommandLogModel::CommandLogModel(QObject *parent) : QAbstractTableModel(parent) {}

void CommandLogModel::record(quint64 id, const QString &text, const QDateTime &when)
{
    if (int(m_rows.size()) >= kMaxRows) {
        const int drop = int(m_rows.size()) - kMaxRows + 1;
        beginRemoveRows(QModelIndex(), 0, drop - 1);
        m_rows.erase(m_rows.begin(), m_rows.begin() + drop);
        endRemoveRows();
    }
    const int row = int(m_rows.size());
    beginInsertRows(QModelIndex(), row, row);
    Row r;
    r.id = id;
    r.time = when;
    r.command = oneLine(text.trimmed());
    m_rows.push_back(std::move(r));
    endInsertRows();
}

bool CommandLogModel::complete(quint64 id, const device::TextReply &reply)
{
    const int row = rowOf(id);
    if (row < 0)
        return false;
    Row &r = m_rows[size_t(row)];
    r.status = reply.status;
    r.reply = replyText(reply);
    Q_EMIT dataChanged(index(row, StatusColumn), index(row, ReplyColumn));
    return true;
}

void CommandLogModel::clear()
{
    if (m_rows.empty())
        return;
    beginResetModel();
    m_rows.clear();
    endResetModel();
}

void CommandLogModel::retranslate()
{
    Q_EMIT headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
    if (!m_rows.empty())
        Q_EMIT dataChanged(index(0, 0), index(int(m_rows.size()) - 1, ColumnCount - 1));
}

int CommandLogModel::rowOf(quint64 id) const
{
    // Replies come back in order: search from the newest.
    for (int i = int(m_rows.size()) - 1; i >= 0; --i)
        if (m_rows[size_t(i)].id == id)
            return i;
    return -1;
}

int CommandLogModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int CommandLogModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QString CommandLogModel::statusText(Status status)
{
    switch (status) {
    case Status::Pending: return tr("waiting");
    case Status::Ok: return tr("OK");
    case Status::Refused: return tr("ERR");
    case Status::Invalid: return tr("invalid");
    case Status::Timeout: return tr("timeout");
    case Status::Cancelled: return tr("cancelled");
    case Status::NotSent: return tr("not sent");
    }
    return QString();
}

QString CommandLogModel::replyText(const device::TextReply &reply)
{
    QStringList parts;
    for (const auto &line : reply.lines)
        parts << oneLine(line);
    if (reply.status != Status::Ok && !reply.why.isEmpty())
        parts << oneLine(reply.why);
    return parts.join(QStringLiteral(" | "));
}

QString CommandLogModel::cellText(const Row &row, int column) const
{
    switch (column) {
    case TimeColumn: return row.time.toString(QStringLiteral("HH:mm:ss.zzz"));
    case CommandColumn: return row.command;
    case StatusColumn: return statusText(row.status);
    case ReplyColumn: return row.reply;
    default: return QString();
    }
}

QVariant CommandLogModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Row &row = m_rows[size_t(index.row())];
    switch (role) {
    case Qt::DisplayRole: return cellText(row, index.column());
    case Qt::ToolTipRole:
        if (index.column() == ReplyColumn && !row.reply.isEmpty())
            return QString(row.reply).replace(QStringLiteral(" | "), QStringLiteral("\n"));
        if (index.column() == TimeColumn)
            return row.time.toString(Qt::ISODateWithMs);
        return {};
    case StatusRole: return int(row.status);
    case IdRole: return row.id;
    default: return {};
    }
}

QVariant CommandLogModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case TimeColumn: return tr("Time");
    case CommandColumn: return tr("Command");
    case StatusColumn: return tr("Status");
    case ReplyColumn: return tr("Reply");
    default: return {};
    }
}

QString CommandLogModel::rowsAsText(QList<int> rows, bool withHeader) const
{
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    QStringList lines;
    if (withHeader) {
        QStringList cells;
        for (int c = 0; c < ColumnCount; ++c)
            cells << headerData(c, Qt::Horizontal).toString();
        lines << cells.join(QLatin1Char('\t'));
    }
    for (int r : rows) {
        if (r < 0 || r >= int(m_rows.size()))
            continue;
        QStringList cells;
        for (int c = 0; c < ColumnCount; ++c)
            cells << cellText(m_rows[size_t(r)], c);
        lines << cells.join(QLatin1Char('\t'));
    }
    if (lines.isEmpty())
        return QString();
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

QString CommandLogModel::allAsText(bool withHeader) const
{
    QList<int> rows;
    rows.reserve(int(m_rows.size()));
    for (int r = 0; r < int(m_rows.size()); ++r)
        rows << r;
    return rowsAsText(rows, withHeader);
}

} // namespace imudesk::models
