// Sample CSV files (header row required; the mag_x, mag_y, mag_z columns in uT for
// `imudesk-cli magcal`): accepted forms, rejected forms with the line named, round trip.
#include "calib/sample_csv.h"
#include "../common/test_main.h"

#include <QTest>

using namespace imudesk::calib;

class TstSampleCsv : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void parse_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<int>("rows");
        QTest::addColumn<QString>("errorContains");
        QTest::newRow("plain") << QByteArray("mag_x,mag_y,mag_z\n1,2,3\n4,5,6\n") << true << 2 << "";
        QTest::newRow("CRLF, spaces, comments, blanks")
            << QByteArray("# capture\r\nmag_x, mag_y, mag_z\r\n\r\n 1.5 , -2e1 ,3\r\n# x\r\n4,5,6") << true << 2 << "";
        QTest::newRow("other columns, any order") << QByteArray("t,mag_z,acc_x,mag_y,mag_x\n0,3,9,2,1\n") << true << 1 << "";
        QTest::newRow("header only") << QByteArray("mag_x,mag_y,mag_z\n") << true << 0 << "";
        QTest::newRow("no header") << QByteArray("1,2,3\n4,5,6\n") << false << 0 << "header";
        QTest::newRow("empty") << QByteArray() << false << 0 << "empty";
        QTest::newRow("short row") << QByteArray("mag_x,mag_y,mag_z\n1,2\n") << false << 0 << "line 2";
        QTest::newRow("not a number") << QByteArray("mag_x,mag_y,mag_z\n1,2,3\n1,x,3\n") << false << 0 << "line 3";
        QTest::newRow("nan") << QByteArray("mag_x,mag_y,mag_z\n1,nan,3\n") << false << 0 << "mag_y";
        QTest::newRow("empty column name") << QByteArray("mag_x,,mag_z\n1,2,3\n") << false << 0 << "empty column";
        QTest::newRow("line too long") << (QByteArray("mag_x,mag_y,mag_z\n") + QByteArray(5000, '1')) << false << 0 << "longer";
        QByteArray wide;
        for (int i = 0; i < 70; ++i)
            wide += "c" + QByteArray::number(i) + ",";
        QTest::newRow("too many columns") << wide << false << 0 << "columns";
    }
    void parse()
    {
        QFETCH(QByteArray, text);
        QFETCH(bool, ok);
        QFETCH(int, rows);
        QFETCH(QString, errorContains);
        SampleTable t;
        QString error;
        QCOMPARE(SampleCsv::parse(text, t, &error), ok);
        if (ok) {
            QCOMPARE(int(t.rows.size()), rows);
            std::vector<Eigen::Vector3d> mag;
            QVERIFY(SampleCsv::magnetometer(t, mag, &error));
            QCOMPARE(int(mag.size()), rows);
            if (rows > 0 && t.columnIndex(QStringLiteral("t")) < 0)
                QCOMPARE(mag[0].x(), t.rows[0][0]);
        } else {
            QVERIFY2(error.contains(errorContains), qPrintable(error));
        }
    }

    void missingMagColumns()
    {
        SampleTable t;
        QVERIFY(SampleCsv::parse("acc_x,acc_y,acc_z\n1,2,3\n", t));
        std::vector<Eigen::Vector3d> mag;
        QString error;
        QVERIFY(!SampleCsv::magnetometer(t, mag, &error));
        QVERIFY(error.contains(QStringLiteral("mag_x")));
    }

    // Only the columns needed are read (issue 53): the vendor CSV's frame tag, the tidy CSV's
    // empty cells and text elsewhere are passed over; the needed ones are still checked.
    void parseColumns_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("device");
        QTest::addColumn<int>("rows");        // -1: refused
        QTest::addColumn<int>("emptyRows");
        QTest::addColumn<QString>("errorContains");
        QTest::newRow("vendor HI91 row") << QByteArray("HI91,pc_counter,mag_x,mag_y,mag_z\nHI91,123456,1,2,3\n")
                                         << QString() << 1 << 0 << "";
        QTest::newRow("tidy: empty cells elsewhere")
            << QByteArray("time_s,mag_x_uT,mag_y_uT,mag_z_uT,lat_deg,lon_deg\n0,1,2,3,,\n0.01,4,5,6,,\n") << QString() << 2 << 0
            << "";
        QTest::newRow("tidy: a frame without mag") << QByteArray("frame_tag,mag_x_uT,mag_y_uT,mag_z_uT\n145,1,2,3\n129,,,\n")
                                                   << QString() << 1 << 1 << "";
        QTest::newRow("session: device B") << QByteArray("device,mag_x_uT,mag_y_uT,mag_z_uT\nA,1,2,3\nB,4,5,6\nB,7,8,9\n")
                                           << QStringLiteral("B") << 2 << 0 << "";
        QTest::newRow("wider than kMaxColumns") << (QByteArray("mag_x,mag_y,mag_z") + QByteArray(",c").repeated(100) + "\n1,2,3"
                                                    + QByteArray(",x").repeated(100) + "\n")
                                                << QString() << 1 << 0 << "";
        QTest::newRow("missing column") << QByteArray("HI91,mag_x,mag_y\nHI91,1,2\n") << QString() << -1 << 0
                                        << "line 1: the column mag_z or mag_z_uT is missing";
        QTest::newRow("bad needed number") << QByteArray("HI91,mag_x,mag_y,mag_z\nHI91,1,2,3\nHI91,1,two,3\n") << QString()
                                           << -1 << 0 << "line 3, column mag_y: 'two' is not a number";
        QTest::newRow("one needed cell empty") << QByteArray("mag_x_uT,mag_y_uT,mag_z_uT,t\n1,,3,0\n") << QString() << -1 << 0
                                               << "line 2, column mag_y_uT";
        QTest::newRow("short row") << QByteArray("HI91,mag_x,mag_y,mag_z\nHI91,1,2\n") << QString() << -1 << 0 << "line 2 has 3";
    }
    void parseColumns()
    {
        QFETCH(QByteArray, text);
        QFETCH(QString, device);
        QFETCH(int, rows);
        QFETCH(int, emptyRows);
        QFETCH(QString, errorContains);
        SampleCsv::ColumnChoice choice;
        choice.wanted = SampleCsv::magnetometerColumns();
        choice.keyColumn = QStringLiteral("device");
        choice.keyValue = device;
        SampleTable t;
        SampleCsv::ColumnInfo info;
        QString error;
        const bool ok = SampleCsv::parseColumns(text, choice, t, &error, &info);
        QVERIFY2(ok == (rows >= 0), qPrintable(error));
        if (!ok) {
            QVERIFY2(error.contains(errorContains), qPrintable(error));
            return;
        }
        QCOMPARE(int(t.rows.size()), rows);
        QCOMPARE(int(info.emptyRows), emptyRows);
        QCOMPARE(t.columns.size(), 3);
        std::vector<Eigen::Vector3d> mag;
        QVERIFY2(SampleCsv::magnetometer(t, mag, &error), qPrintable(error));
        QCOMPARE(int(mag.size()), rows);
        if (rows > 0 && device == QLatin1String("B"))
            QCOMPARE(mag[0], Eigen::Vector3d(4, 5, 6));
        else if (rows > 0)
            QCOMPARE(mag[0], Eigen::Vector3d(1, 2, 3));
    }

    void roundTrip()
    {
        SampleTable t;
        t.columns = {QStringLiteral("mag_x"), QStringLiteral("mag_y"), QStringLiteral("mag_z")};
        t.rows = {{1.0 / 3, -2.5e-7, 1e300}, {0, -0.0, 42}};
        SampleTable back;
        QVERIFY(SampleCsv::parse(SampleCsv::write(t), back));
        QCOMPARE(back.columns, t.columns);
        QCOMPARE(back.rows, t.rows); // 17 significant digits: exact
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstSampleCsv)
#include "tst_sample_csv.moc"
