#include "mat_file.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStorageInfo>
#include <QTemporaryDir>
#include <QtEndian>

#include <matio.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <system_error>
#include <thread>

namespace imudesk::format::mat {

namespace {

constexpr size_t kMaxNameLength = 63; // MATLAB's namelengthmax

// Version 5 data types of a top-level element.
constexpr quint32 kMiMatrix = 14;
constexpr quint32 kMiCompressed = 15;

// MATLAB's keywords (iskeyword): no variable or field may be named so.
const char *const kKeywords[] = {
    "break", "case", "catch", "classdef", "continue", "else", "elseif", "end", "for", "function",
    "global", "if", "otherwise", "parfor", "persistent", "return", "spmd", "switch", "try", "while",
};

bool isLetter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool isNameChar(char c) { return isLetter(c) || (c >= '0' && c <= '9') || c == '_'; }

bool isKeyword(const std::string &name)
{
    return std::any_of(std::begin(kKeywords), std::end(kKeywords), [&](const char *k) { return name == k; });
}

// A valid MATLAB name made of any text: every other character (every byte of one beyond ASCII)
// becomes '_', an 'x' goes before one that does not begin with a letter or is a keyword, and
// the name is cut at 63 characters.
std::string validName(const std::string &text)
{
    std::string name;
    name.reserve(text.size() + 1);
    for (char c : text)
        name.push_back(isNameChar(c) ? c : '_');
    if (name.empty() || !isLetter(name[0]) || isKeyword(name))
        name.insert(name.begin(), 'x');
    if (name.size() > kMaxNameLength)
        name.resize(kMaxNameLength);
    return name;
}

bool isValidName(const std::string &name) { return !name.empty() && validName(name) == name; }

bool isReserved(const std::string &name) { return name == "units" || name == "columns" || name == "info"; }

// name, or name_2, name_3, ... (cut to stay within 63 characters), whichever is not in taken yet.
std::string uniqueName(const std::string &name, const std::vector<std::string> &taken)
{
    const auto isTaken = [&](const std::string &n) { return std::find(taken.begin(), taken.end(), n) != taken.end(); };
    if (!isTaken(name))
        return name;
    for (int i = 2;; ++i) {
        const std::string suffix = "_" + std::to_string(i);
        const std::string n = name.substr(0, kMaxNameLength - suffix.size()) + suffix;
        if (!isTaken(n))
            return n;
    }
}

// The stream matio writes through: the FILE * its struct _mat_t (matio_private.h) begins with,
// in every matio 1.5. The layout is trusted only when the struct's fourth member, the file
// name, is what Mat_GetFilename() gives; null otherwise.
FILE *matStream(mat_t *mat)
{
    void *members[4];
    std::memcpy(members, static_cast<const void *>(mat), sizeof members);
    if (!members[0] || members[3] != static_cast<const void *>(Mat_GetFilename(mat)))
        return nullptr;
    return static_cast<FILE *>(members[0]);
}

// A 1xn char row of text (UTF-8) in UTF-16 code units, 0x0 when empty; matio keeps a copy.
matvar_t *charVariable(const std::string &text)
{
    const QString s = QString::fromUtf8(text.data(), qsizetype(text.size()));
    size_t dims[2] = {s.isEmpty() ? 0u : 1u, size_t(s.size())};
    void *data = s.isEmpty() ? nullptr : const_cast<void *>(static_cast<const void *>(s.utf16()));
    return Mat_VarCreate(nullptr, MAT_C_CHAR, MAT_T_UINT16, 2, dims, data, 0);
}

// A 1x1 struct of char fields (name, text); null when matio fails.
matvar_t *charStruct(const std::vector<std::pair<std::string, std::string>> &entries)
{
    std::vector<const char *> names;
    for (const auto &e : entries)
        names.push_back(e.first.c_str());
    names.push_back(nullptr);
    size_t dims[2] = {1, 1};
    matvar_t *s = Mat_VarCreateStruct2(nullptr, 2, dims, names.data());
    if (!s)
        return nullptr;
    for (size_t i = 0; i < entries.size(); ++i) {
        matvar_t *c = charVariable(entries[i].second);
        if (!c) {
            Mat_VarFree(s);
            return nullptr;
        }
        Mat_VarSetStructFieldByIndex(s, i, 0, c);
    }
    return s;
}

std::string joined(const std::vector<std::string> &parts)
{
    std::string s;
    for (const std::string &p : parts) {
        if (!s.empty())
            s += ' ';
        s += p;
    }
    return s;
}

// A struct variable: the data fields, each an N-by-k slice of data (N rows column-major over
// every column, matio reading it in place), then units, columns and info. Null when matio fails.
matvar_t *structVariable(const std::string &name, const std::vector<MatFile::Field> &fields,
                         const std::vector<size_t> &firstColumn,
                         const std::vector<std::pair<std::string, std::string>> &info, const double *data,
                         uint64_t rows)
{
    std::vector<const char *> names;
    for (const MatFile::Field &f : fields)
        names.push_back(f.name.c_str());
    for (const char *n : {"units", "columns", "info"})
        names.push_back(n);
    names.push_back(nullptr);
    size_t one[2] = {1, 1};
    matvar_t *var = Mat_VarCreateStruct2(name.c_str(), 2, one, names.data());
    if (!var)
        return nullptr;
    std::vector<std::pair<std::string, std::string>> units, columns;
    for (size_t i = 0; i < fields.size(); ++i) {
        const MatFile::Field &f = fields[i];
        size_t dims[2] = {size_t(rows), std::max<size_t>(1, f.components.size())};
        // matio only reads it (MAT_F_DONT_COPY_DATA: nor frees it).
        void *slice = rows ? const_cast<double *>(data + firstColumn[i] * rows) : nullptr;
        matvar_t *m = Mat_VarCreate(nullptr, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, slice, MAT_F_DONT_COPY_DATA);
        if (!m) {
            Mat_VarFree(var);
            return nullptr;
        }
        Mat_VarSetStructFieldByIndex(var, i, 0, m);
        units.emplace_back(f.name, f.unit);
        columns.emplace_back(f.name, joined(f.components));
    }
    const std::vector<std::pair<std::string, std::string>> *subs[] = {&units, &columns, &info};
    for (size_t k = 0; k < 3; ++k) {
        matvar_t *s = charStruct(*subs[k]);
        if (!s) {
            Mat_VarFree(var);
            return nullptr;
        }
        Mat_VarSetStructFieldByIndex(var, fields.size() + k, 0, s);
    }
    return var;
}

// While it lives, drops this process's page-table entries of a shared file mapping every
// kTrimPeriod (madvise MADV_DONTNEED, from a thread of its own), so that the pages matio has
// read do not stay counted in the process's resident set until the mapping goes: the pages
// stay in the page cache, and one read again is mapped again from there (the contents of a
// shared file mapping survive MADV_DONTNEED), so nothing matio sees changes.
class MappingTrimmer {
public:
    static constexpr std::chrono::milliseconds kTrimPeriod{25};
    MappingTrimmer(const void *map, size_t bytes) : m_map(map), m_bytes(bytes)
    {
        if (!m_map)
            return;
        try {
            m_thread = std::thread([this] { run(); });
        } catch (const std::system_error &) {
            // no thread to be had: the pages stay mapped until the mapping goes, nothing worse
        }
    }
    ~MappingTrimmer()
    {
        if (!m_thread.joinable())
            return;
        {
            std::lock_guard lock(m_mutex);
            m_stop = true;
        }
        m_wake.notify_one();
        m_thread.join();
    }
    MappingTrimmer(const MappingTrimmer &) = delete;
    MappingTrimmer &operator=(const MappingTrimmer &) = delete;

private:
    void run()
    {
        std::unique_lock lock(m_mutex);
        while (!m_wake.wait_for(lock, kTrimPeriod, [this] { return m_stop; }))
            SpoolFile::dropPages(m_map, m_bytes);
    }

    const void *m_map;
    size_t m_bytes;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    bool m_stop = false;
    std::thread m_thread;
};

// Why writing path failed: the errno when it says (matio's own calls may have replaced it by
// then), and the room left on its disk.
QString writeFailure(const QString &path, int errnoValue)
{
    const QString why = SpoolFile::saysDiskFull(errnoValue) ? QString::fromLocal8Bit(std::strerror(errnoValue))
                                                            : QStringLiteral("a write failed");
    const qint64 room = QStorageInfo(QFileInfo(path).absolutePath()).bytesAvailable();
    return QStringLiteral("Writing %1 failed: %2 (%3 bytes free on its disk)").arg(path, why).arg(room);
}

} // namespace

MatFile::MatFile(const QString &spoolParent) : m_spoolParent(spoolParent) {}

MatFile::~MatFile()
{
    m_vars.clear(); // closes the spools; m_dir then removes the folder with them
}

bool MatFile::fail(const QString &what)
{
    m_error = what;
    return false;
}

bool MatFile::ensureSpoolDir()
{
    if (m_dir)
        return true;
    const QString parent = m_spoolParent.isEmpty() ? QDir::tempPath() : m_spoolParent;
    auto dir = std::make_unique<QTemporaryDir>(parent + QStringLiteral("/imudesk-mat-XXXXXX"));
    if (!dir->isValid())
        return fail(QStringLiteral("Cannot create a spool folder in %1: %2").arg(parent, dir->errorString()));
    m_dir = std::move(dir);
    return true;
}

int MatFile::addStruct(const std::string &varName, const std::map<std::string, std::string> &info,
                       std::vector<Field> fields)
{
    const QString what = QString::fromStdString(varName);
    if (fields.empty()) {
        fail(QStringLiteral("%1: a struct needs a data field").arg(what));
        return -1;
    }
    Var v;
    std::vector<std::string> taken;
    size_t textBytes = 0; // of every name and text in the variable
    for (const Field &f : fields) {
        const QString field = QString::fromStdString(f.name);
        if (!isValidName(f.name) || isReserved(f.name)) {
            fail(QStringLiteral("%1: \"%2\" is not a valid MATLAB name or is reserved").arg(what, field));
            return -1;
        }
        if (std::find(taken.begin(), taken.end(), f.name) != taken.end()) {
            fail(QStringLiteral("%1: the field %2 is there twice").arg(what, field));
            return -1;
        }
        taken.push_back(f.name);
        for (const std::string &c : f.components) {
            if (c.empty() || c.find_first_of(" \t\r\n") != std::string::npos) {
                fail(QStringLiteral("%1: a component name of %2 is empty or has a space").arg(what, field));
                return -1;
            }
            textBytes += c.size() + 1;
        }
        v.firstColumn.push_back(v.columns);
        v.columns += std::max<size_t>(1, f.components.size());
        textBytes += 3 * f.name.size() + f.unit.size();
    }
    taken.clear();
    for (const auto &[key, value] : info) {
        const std::string name = uniqueName(validName(key), taken);
        taken.push_back(name);
        v.info.emplace_back(name, value);
        textBytes += name.size() + value.size();
    }
    taken.clear();
    for (const Var &other : m_vars)
        taken.push_back(other.name);
    v.name = uniqueName(validName(varName), taken);
    // The variable's bytes beside its doubles: tags, array flags, dimensions and names of every
    // element (well under 256 bytes each), text in UTF-16.
    const uint64_t overhead = 4096 + 256 * (3 * fields.size() + v.info.size()) + 2 * uint64_t(textBytes);
    const uint64_t rowBytes = uint64_t(v.columns) * sizeof(double);
    v.maxRows = overhead < kMaxVariableBytes ? (kMaxVariableBytes - overhead) / rowBytes : 0;

    if (!ensureSpoolDir())
        return -1;
    const size_t index = m_vars.size();
    v.spoolPath = m_dir->filePath(QStringLiteral("%1.spool").arg(index));
    if (const QString e = v.spool.create(v.spoolPath, true); !e.isEmpty()) {
        fail(QStringLiteral("Cannot create the spool %1: %2").arg(v.spoolPath, e));
        return -1;
    }
    v.tail.assign(v.columns * kBlockRows, 0.0);
    v.fields = std::move(fields);
    m_vars.push_back(std::move(v));
    return int(index);
}

bool MatFile::flushBlock(Var &v)
{
    const size_t bytes = v.tail.size() * sizeof(double);
    if (const QString e = v.spool.writeAt(v.tail.data(), bytes, v.spooledBlocks * bytes); !e.isEmpty()) {
        const QString name = QString::fromStdString(v.name);
        return fail(QStringLiteral("Cannot spool the rows of %1 to %2: %3").arg(name, v.spoolPath, e));
    }
    ++v.spooledBlocks;
    v.tailRows = 0;
    return true;
}

bool MatFile::appendRow(int structIndex, const double *values)
{
    if (structIndex < 0 || size_t(structIndex) >= m_vars.size())
        return fail(QStringLiteral("There is no struct %1").arg(structIndex));
    Var &v = m_vars[size_t(structIndex)];
    if (rows(structIndex) >= v.maxRows)
        return fail(QStringLiteral("%1 holds %2 rows of %3 columns, the most a MAT-file variable of version 5 takes")
                        .arg(QString::fromStdString(v.name))
                        .arg(v.maxRows)
                        .arg(v.columns));
    if (v.tailRows == kBlockRows && !flushBlock(v))
        return false;
    double *row = v.tail.data() + v.tailRows;
    for (size_t c = 0; c < v.columns; ++c)
        row[c * kBlockRows] = values[c];
    ++v.tailRows;
    return true;
}

uint64_t MatFile::rows(int structIndex) const
{
    if (structIndex < 0 || size_t(structIndex) >= m_vars.size())
        return 0;
    const Var &v = m_vars[size_t(structIndex)];
    return v.spooledBlocks * kBlockRows + v.tailRows;
}

size_t MatFile::columnCount(int structIndex) const
{
    if (structIndex < 0 || size_t(structIndex) >= m_vars.size())
        return 0;
    return m_vars[size_t(structIndex)].columns;
}

const std::string &MatFile::variableName(int structIndex) const
{
    static const std::string none;
    if (structIndex < 0 || size_t(structIndex) >= m_vars.size())
        return none;
    return m_vars[size_t(structIndex)].name;
}

bool MatFile::assemble(Var &v, size_t index, Assembled &a)
{
    const uint64_t rowCount = rows(int(index));
    a.bytes = size_t(rowCount * v.columns * sizeof(double));
    if (a.bytes == 0)
        return true;
    const QString path = m_dir->filePath(QStringLiteral("%1.data").arg(index));
    if (const QString e = a.file.create(path, false); !e.isEmpty())
        return fail(QStringLiteral("Cannot create %1: %2").arg(path, e));
    // Room for all of it now, or a clear failure (a file system that cannot say goes on).
    if (const QString e = a.file.reserve(a.bytes); !e.isEmpty())
        return fail(QStringLiteral("Cannot make room for %1 bytes in %2: %3").arg(a.bytes).arg(path, e));
    const QString failure =
        QStringLiteral("Cannot gather the rows of %1 in %2").arg(QString::fromStdString(v.name), path);
    const size_t segment = kBlockRows * sizeof(double);
    const uint64_t blockBytes = uint64_t(segment) * v.columns;
    for (size_t c = 0; c < v.columns; ++c) {
        const uint64_t column = uint64_t(c) * rowCount * sizeof(double);
        for (uint64_t b = 0; b < v.spooledBlocks; ++b)
            if (const QString e = v.spool.copyTo(b * blockBytes + c * segment, a.file, column + b * segment, segment,
                                                 m_copyBuffer);
                !e.isEmpty())
                return fail(QStringLiteral("%1: %2").arg(failure, e));
        if (v.tailRows > 0) {
            const uint64_t at = column + v.spooledBlocks * segment;
            if (const QString e = a.file.writeAt(v.tail.data() + c * kBlockRows, v.tailRows * sizeof(double), at);
                !e.isEmpty())
                return fail(QStringLiteral("%1: %2").arg(failure, e));
        }
    }
    QString error;
    a.map = a.file.map(a.bytes, &error);
    if (!a.map)
        return fail(QStringLiteral("Cannot map %1: %2").arg(path, error));
    return true;
}

void MatFile::release(Assembled &a)
{
    a.file.close(true);
    a.map = nullptr;
    a.bytes = 0;
}

bool MatFile::checkTags(const QString &path, size_t variables)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return fail(QStringLiteral("Cannot read %1 back: %2").arg(path, file.errorString()));
    const qint64 size = file.size();
    char header[128];
    if (file.read(header, sizeof header) != qint64(sizeof header))
        return fail(QStringLiteral("%1 came out shorter than its header").arg(path));
    const bool little = header[126] == 'I' && header[127] == 'M'; // the endian indicator "MI" as a uint16
    qint64 offset = sizeof header;
    size_t count = 0;
    while (offset < size) {
        uchar tag[8];
        if (!file.seek(offset) || file.read(reinterpret_cast<char *>(tag), sizeof tag) != qint64(sizeof tag))
            break;
        const quint32 type = little ? qFromLittleEndian<quint32>(tag) : qFromBigEndian<quint32>(tag);
        quint64 bytes = little ? qFromLittleEndian<quint32>(tag + 4) : qFromBigEndian<quint32>(tag + 4);
        if (type != kMiMatrix && type != kMiCompressed)
            break;
        if (type == kMiMatrix)
            bytes = (bytes + 7) & ~quint64(7);
        offset += qint64(sizeof tag + bytes);
        ++count;
    }
    if (offset != size || count != variables)
        return fail(QStringLiteral("%1 came out inconsistent: %2 bytes, which its %3 variables' sizes do not add up to"
                                   " (disk full?)")
                        .arg(path)
                        .arg(size)
                        .arg(variables));
    return true;
}

bool MatFile::write(const QString &path, Compression compression)
{
    {
        QFile probe(path); // matio says nothing of why it cannot create a file
        if (!probe.open(QIODevice::WriteOnly | QIODevice::Truncate))
            return fail(QStringLiteral("Cannot create %1: %2").arg(path, probe.errorString()));
    }
    mat_t *mat = Mat_CreateVer(QFile::encodeName(path).constData(), nullptr, MAT_FT_MAT5);
    if (!mat) {
        QFile::remove(path);
        return fail(QStringLiteral("matio cannot create %1").arg(path));
    }
    FILE *stream = matStream(mat);
    const matio_compression how = compression == Compression::Zlib ? MAT_COMPRESSION_ZLIB : MAT_COMPRESSION_NONE;
    bool ok = true;
    for (size_t i = 0; ok && i < m_vars.size(); ++i) {
        Var &v = m_vars[i];
        Assembled a;
        ok = assemble(v, i, a);
        if (ok) {
            const QString name = QString::fromStdString(v.name);
            matvar_t *var = structVariable(v.name, v.fields, v.firstColumn, v.info, static_cast<const double *>(a.map),
                                           rows(int(i)));
            if (!var) {
                ok = fail(QStringLiteral("matio cannot build the variable %1 (out of memory?)").arg(name));
            } else {
                int result, writeErrno;
                {
                    const MappingTrimmer trimmer(a.map, a.bytes);
                    errno = 0;
                    result = Mat_VarWrite(mat, var, how);
                    writeErrno = errno;
                }
                Mat_VarFree(var);
                if (result != 0)
                    ok = fail(QStringLiteral("matio cannot write %1 to %2 (its error %3)").arg(name, path).arg(result));
                else if (stream && std::ferror(stream))
                    ok = fail(writeFailure(path, writeErrno));
            }
        }
        release(a);
    }
    if (ok && stream) {
        errno = 0;
        if (std::fflush(stream) != 0 || std::ferror(stream))
            ok = fail(writeFailure(path, errno));
    }
    const int closed = Mat_Close(mat);
    if (ok && closed != 0)
        ok = fail(QStringLiteral("Cannot close %1 (matio's error %2)").arg(path).arg(closed));
    if (ok)
        ok = checkTags(path, m_vars.size());
    if (!ok)
        QFile::remove(path);
    return ok;
}

} // namespace imudesk::format::mat
