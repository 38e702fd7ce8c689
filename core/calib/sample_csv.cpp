#include "calib/sample_csv.h"

#include <cmath>

namespace imudesk::calib {

namespace {

// The rows of a CSV text: each line that is neither empty nor a comment ('#'), CR and spaces
// trimmed, split at commas, with its line number. Stops (false) at a line longer than
// kMaxLineLength or with more than maxColumns fields (failWith says which), or when row()
// returns false (it has said why).
template <typename Fail, typename Row>
bool forEachRow(QByteArrayView data, int maxColumns, const Fail &failWith, const Row &row)
{
    qsizetype pos = 0;
    int lineNo = 0;
    while (pos < data.size()) {
        qsizetype end = pos;
        while (end < data.size() && data[end] != '\n')
            ++end;
        ++lineNo;
        QByteArrayView line = data.sliced(pos, end - pos);
        pos = end + 1;
        if (line.size() > SampleCsv::kMaxLineLength)
            return failWith(SampleCsv::tr("line %1 is longer than %2 characters").arg(lineNo).arg(SampleCsv::kMaxLineLength));
        if (!line.isEmpty() && line.back() == '\r')
            line.chop(1);
        const QByteArray trimmed = line.toByteArray().trimmed();
        if (trimmed.isEmpty() || trimmed.startsWith('#'))
            continue;
        const QList<QByteArray> fields = trimmed.split(',');
        if (fields.size() > maxColumns)
            return failWith(SampleCsv::tr("line %1 has more than %2 columns").arg(lineNo).arg(maxColumns));
        if (!row(lineNo, fields))
            return false;
    }
    return true;
}

} // namespace

int SampleTable::columnIndex(const QString &name) const
{
    for (int i = 0; i < columns.size(); ++i)
        if (columns.at(i).compare(name, Qt::CaseInsensitive) == 0)
            return i;
    return -1;
}

bool SampleCsv::parse(QByteArrayView data, SampleTable &out, QString *error)
{
    auto failWith = [error](const QString &message) {
        if (error)
            *error = message;
        return false;
    };
    SampleTable table;
    bool haveHeader = false;
    const bool read = forEachRow(data, kMaxColumns, failWith, [&](int lineNo, const QList<QByteArray> &fields) {
        if (!haveHeader) {
            for (const QByteArray &f : fields) {
                const QString name = QString::fromUtf8(f.trimmed());
                if (name.isEmpty())
                    return failWith(tr("line %1: the header has an empty column name").arg(lineNo));
                bool isNumber = false;
                name.toDouble(&isNumber);
                if (isNumber)
                    return failWith(tr("line %1: a header row of column names is required (e.g. mag_x,mag_y,mag_z)")
                                        .arg(lineNo));
                table.columns << name;
            }
            haveHeader = true;
            return true;
        }
        if (fields.size() != table.columns.size())
            return failWith(tr("line %1 has %2 values, the header has %3 columns")
                                .arg(lineNo)
                                .arg(fields.size())
                                .arg(table.columns.size()));
        if (table.rows.size() >= kMaxRows)
            return failWith(tr("more than %1 rows").arg(kMaxRows));
        std::vector<double> row;
        row.reserve(size_t(fields.size()));
        for (int c = 0; c < fields.size(); ++c) {
            bool ok = false;
            const double v = fields.at(c).trimmed().toDouble(&ok);
            if (!ok || !std::isfinite(v))
                return failWith(tr("line %1, column %2: '%3' is not a number")
                                    .arg(lineNo)
                                    .arg(table.columns.at(c))
                                    .arg(QString::fromUtf8(fields.at(c).trimmed().left(40))));
            row.push_back(v);
        }
        table.rows.push_back(std::move(row));
        return true;
    });
    if (!read)
        return false;
    if (!haveHeader)
        return failWith(tr("the file is empty: a header row and samples are needed"));
    out = std::move(table);
    return true;
}

QList<QStringList> SampleCsv::magnetometerColumns()
{
    return {{QStringLiteral("mag_x"), QStringLiteral("mag_x_uT")},
            {QStringLiteral("mag_y"), QStringLiteral("mag_y_uT")},
            {QStringLiteral("mag_z"), QStringLiteral("mag_z_uT")}};
}

bool SampleCsv::parseColumns(QByteArrayView data, const ColumnChoice &choice, SampleTable &out, QString *error,
                             ColumnInfo *info)
{
    auto failWith = [error](const QString &message) {
        if (error)
            *error = message;
        return false;
    };
    SampleTable table;
    ColumnInfo found;
    std::vector<int> index;     // file column of each wanted column
    int keyIndex = -1;
    int headerColumns = 0;
    bool haveHeader = false;
    const bool read = forEachRow(data, kMaxFileColumns, failWith, [&](int lineNo, const QList<QByteArray> &fields) {
        if (!haveHeader) {
            QStringList names;
            for (const QByteArray &f : fields)
                names << QString::fromUtf8(f.trimmed());
            auto columnOf = [&names](const QString &name) {
                for (int i = 0; i < names.size(); ++i)
                    if (names.at(i).compare(name, Qt::CaseInsensitive) == 0)
                        return i;
                return -1;
            };
            for (const QStringList &aliases : choice.wanted) {
                int at = -1;
                for (const QString &a : aliases)
                    if ((at = columnOf(a)) >= 0)
                        break;
                if (at < 0) {
                    QStringList needed;
                    for (const QStringList &w : choice.wanted)
                        needed << w.value(0);
                    return failWith(tr("line %1: the column %2 is missing (needed: %3); the header has: %4")
                                        .arg(lineNo)
                                        .arg(aliases.join(QStringLiteral(" or ")), needed.join(QStringLiteral(", ")),
                                             names.join(QStringLiteral(", ")).left(400)));
                }
                bool isNumber = false;
                names.at(at).toDouble(&isNumber);
                if (isNumber)
                    return failWith(tr("line %1: a header row of column names is required (e.g. mag_x,mag_y,mag_z)")
                                        .arg(lineNo));
                index.push_back(at);
                table.columns << names.at(at);
            }
            keyIndex = choice.keyColumn.isEmpty() ? -1 : columnOf(choice.keyColumn);
            headerColumns = int(fields.size());
            haveHeader = true;
            return true;
        }
        if (fields.size() != headerColumns)
            return failWith(tr("line %1 has %2 values, the header has %3 columns")
                                .arg(lineNo)
                                .arg(fields.size())
                                .arg(headerColumns));
        if (keyIndex >= 0) {
            const QString key = QString::fromUtf8(fields.at(keyIndex).trimmed());
            if (!found.keys.contains(key) && found.keys.size() < 100)
                found.keys << key;
            if (!choice.keyValue.isEmpty() && key != choice.keyValue) {
                ++found.otherRows;
                return true;
            }
        }
        bool allEmpty = true;
        for (int at : index)
            allEmpty = allEmpty && fields.at(at).trimmed().isEmpty();
        if (allEmpty && !index.empty()) {
            ++found.emptyRows;
            return true;
        }
        if (table.rows.size() >= kMaxRows)
            return failWith(tr("more than %1 rows").arg(kMaxRows));
        std::vector<double> row;
        row.reserve(index.size());
        for (size_t c = 0; c < index.size(); ++c) {
            const QByteArray cell = fields.at(index[c]).trimmed();
            bool ok = false;
            const double v = cell.toDouble(&ok);
            if (!ok || !std::isfinite(v))
                return failWith(tr("line %1, column %2: '%3' is not a number")
                                    .arg(lineNo)
                                    .arg(table.columns.at(int(c)))
                                    .arg(QString::fromUtf8(cell.left(40))));
            row.push_back(v);
        }
        table.rows.push_back(std::move(row));
        return true;
    });
    if (!read)
        return false;
    if (!haveHeader)
        return failWith(tr("the file is empty: a header row and samples are needed"));
    out = std::move(table);
    if (info)
        *info = std::move(found);
    return true;
}

QByteArray SampleCsv::write(const SampleTable &table)
{
    QByteArray out = table.columns.join(QLatin1Char(',')).toUtf8() + '\n';
    for (const auto &row : table.rows) {
        for (size_t i = 0; i < row.size(); ++i) {
            if (i)
                out += ',';
            out += QByteArray::number(row[i], 'g', 17);
        }
        out += '\n';
    }
    return out;
}

bool SampleCsv::magnetometer(const SampleTable &table, std::vector<Eigen::Vector3d> &out, QString *error)
{
    const QList<QStringList> names = magnetometerColumns();
    int axis[3] = {-1, -1, -1};
    for (int a = 0; a < 3; ++a)
        for (const QString &name : names.at(a))
            if (axis[a] < 0)
                axis[a] = table.columnIndex(name);
    const int x = axis[0], y = axis[1], z = axis[2];
    if (x < 0 || y < 0 || z < 0) {
        if (error)
            *error = tr("the columns mag_x, mag_y and mag_z (µT) are needed; the header has: %1")
                         .arg(table.columns.join(QStringLiteral(", ")));
        return false;
    }
    out.clear();
    out.reserve(table.rows.size());
    for (const auto &row : table.rows)
        out.emplace_back(row[size_t(x)], row[size_t(y)], row[size_t(z)]);
    return true;
}

} // namespace imudesk::calib
