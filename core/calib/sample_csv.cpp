#include "calib/sample_csv.h"

#include <cmath>

namespace imudesk::calib {

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
    qsizetype pos = 0;
    int lineNo = 0;
    while (pos < data.size()) {
        qsizetype end = pos;
        while (end < data.size() && data[end] != '\n')
            ++end;
        ++lineNo;
        QByteArrayView line = data.sliced(pos, end - pos);
        pos = end + 1;
        if (line.size() > kMaxLineLength)
            return failWith(tr("line %1 is longer than %2 characters").arg(lineNo).arg(kMaxLineLength));
        if (!line.isEmpty() && line.back() == '\r')
            line.chop(1);
        const QByteArray trimmed = line.toByteArray().trimmed();
        if (trimmed.isEmpty() || trimmed.startsWith('#'))
            continue;
        const QList<QByteArray> fields = trimmed.split(',');
        if (fields.size() > kMaxColumns)
            return failWith(tr("line %1 has more than %2 columns").arg(lineNo).arg(kMaxColumns));
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
            continue;
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
    }
    if (!haveHeader)
        return failWith(tr("the file is empty: a header row and samples are needed"));
    out = std::move(table);
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
    const int x = table.columnIndex(QStringLiteral("mag_x")), y = table.columnIndex(QStringLiteral("mag_y")),
              z = table.columnIndex(QStringLiteral("mag_z"));
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
