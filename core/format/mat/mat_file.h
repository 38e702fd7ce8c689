#pragma once
// Writes a MATLAB MAT-file of version 5 (what MATLAB's save -v7 writes; MATLAB's load,
// scipy.io.loadmat and Octave read it) through matio. Each struct added is one variable, a 1x1
// struct of
//   - one N-by-k double matrix per data field (N rows, k its components, 1 when it names none),
//     NaN where a row has no value; 0-by-k when the struct has no rows;
//   - units: a 1x1 struct, per data field its unit (char);
//   - columns: a 1x1 struct, per data field its component names separated by spaces ('x y z'),
//     '' for a field without component names;
//   - info: a 1x1 struct of the descriptive entries given (product, serial, firmware, ...), char,
//     in the order of their keys.
// Char data is UTF-16, as MATLAB keeps char (miUINT16; scipy decodes what is beyond ASCII with
// loadmat(..., uint16_codec='utf-16-le')); '' is 0x0. Names are valid MATLAB identifiers (letters,
// digits and '_', a letter first, 63 characters at most, no keyword): a variable's name and the
// info keys are made so ("SN 0042" gives SN_0042, "2nd device" x2nd_device) and unique ("_2", "_3",
// ...); a data field's name must be one already, and not units, columns or info.
//
// Rows are not kept in memory beyond a block: an export of an hour at 1 kHz is 3.6 million rows
// of some 25 values per device. A struct's rows go to its spool file, in a QTemporaryDir (in the
// system's temporary folder, TMPDIR, unless another parent is given) removed with the object.
// The spool is a sequence of blocks of kBlockRows rows, each block column-major (its kBlockRows
// values of column 0, then those of column 1, ...); the last, partial block stays in memory.
// write() gathers each struct in turn into a data file of its N rows column-major over all its
// columns (column c from byte 8*N*c; the kernel copies the blocks' segments, copy_file_range),
// where every field's N-by-k matrix is a contiguous column-major slice. matio's version 5 writer
// wants every matrix's whole data at hand: it gets pointers into a read-only mapping (mmap) of
// the data file, so the rows are in file-backed pages of the page cache, not in this process's
// memory; a thread of write() unmaps the pages matio has read every 25 ms (madvise), so that they
// do not stay counted in the process's resident set either. The data file is removed once its
// variable is written: the spools' disk needs room for the spools and the largest struct again.
//
// Compression::Zlib (the default) writes each variable as one zlib stream (miCOMPRESSED, as
// save -v7 does), at matio's level (zlib's default, 6), on one core: measured here, 720 MB of
// doubles (3.6 million rows of 25 columns, sensor-like values) took 33 s and came to 620 MB;
// Compression::None wrote the same in 3 s (720 MB). Debian 12's matio 1.5.23 has zlib.
//
// A variable of version 5 holds at most 2^31 - 1 bytes (MATLAB's limit for files before -v7.3;
// the format's sizes are 32-bit), so a struct takes some 2^31 / (8 * columns) rows (10.7 million
// of 25 columns, three hours at 1 kHz); appendRow() refuses the rows beyond.
//
// Errors: matio 1.5.23 does not check its fwrite() calls (on a full disk Mat_VarWrite and
// Mat_Close return success and leave a truncated file), so write() tests the error flag of
// matio's FILE after every variable, the FILE found at the start of matio's private struct
// _mat_t (its layout in every matio 1.5, checked at run time against Mat_GetFilename()), and
// then walks the written file's top-level tags (their count, and their sizes against the file's
// size). A failed write() removes the file and keeps the spools: write() can be tried again
// (elsewhere, or once room is made) and rows can still be appended. A failed appendRow() (the
// spools' disk full) adds no row and changes nothing else.
//
// Linux (file descriptors, copy_file_range, mmap). Plain value class; not thread-safe.
#include "format/mat/spool_file.h"

#include <QString>

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

class QTemporaryDir;

namespace imudesk::format::mat {

class MatFile {
public:
    struct Field {
        std::string name;                    // the matrix's name in the struct, e.g. "acc"
        std::string unit;                    // e.g. "m/s^2"
        std::vector<std::string> components; // its column names, e.g. {"x", "y", "z"}; none: one column
    };
    enum class Compression { None, Zlib };
    // Rows a spool block holds (a column's segment of a block is 64 KiB).
    static constexpr size_t kBlockRows = 8192;
    // The largest variable of version 5, bytes.
    static constexpr uint64_t kMaxVariableBytes = (uint64_t(1) << 31) - 1;

    // spoolParent: the folder the spool folder is made in; empty: the system's temporary folder.
    explicit MatFile(const QString &spoolParent = QString());
    ~MatFile();
    MatFile(const MatFile &) = delete;
    MatFile &operator=(const MatFile &) = delete;

    // A struct variable named varName (made valid and unique, see variableName()) with the info
    // entries (keys made valid) and the data fields, in this order. Returns its index (from 0), or
    // -1 and error() (no fields, a field's name invalid or twice, the spool not created).
    int addStruct(const std::string &varName, const std::map<std::string, std::string> &info,
                  std::vector<Field> fields);
    // One row of struct structIndex: every field's components in the fields' order, concatenated
    // (columnCount() values). False and error() when the spool cannot be written or the struct
    // holds all the rows it can; the row is then not added.
    bool appendRow(int structIndex, const double *values);
    uint64_t rows(int structIndex) const;
    size_t columnCount(int structIndex) const;
    const std::string &variableName(int structIndex) const;
    int structCount() const { return int(m_vars.size()); }

    // Writes the file (replacing one there), every struct added. False and error() on failure (the
    // file not created, a disk full), the file then removed.
    bool write(const QString &path, Compression compression = Compression::Zlib);

    const QString &error() const { return m_error; }

private:
    struct Var {
        std::string name;
        std::vector<std::pair<std::string, std::string>> info; // valid keys, values
        std::vector<Field> fields;
        std::vector<size_t> firstColumn; // per field, its first column in a row
        size_t columns = 0;
        uint64_t maxRows = 0;
        QString spoolPath;
        SpoolFile spool;
        uint64_t spooledBlocks = 0;
        size_t tailRows = 0;
        std::vector<double> tail; // the partial block: kBlockRows values per column
    };
    // A struct's rows assembled column-major into a data file, mapped read-only.
    struct Assembled {
        SpoolFile file;
        const void *map = nullptr;
        size_t bytes = 0;
    };

    bool fail(const QString &what);
    bool ensureSpoolDir();
    bool flushBlock(Var &v);
    bool assemble(Var &v, size_t index, Assembled &out);
    static void release(Assembled &a);
    bool checkTags(const QString &path, size_t variables);

    QString m_spoolParent;
    std::unique_ptr<QTemporaryDir> m_dir;
    std::vector<Var> m_vars;
    QString m_error;
    std::vector<char> m_copyBuffer; // for a copy between two spools that the system cannot make
};

} // namespace imudesk::format::mat
