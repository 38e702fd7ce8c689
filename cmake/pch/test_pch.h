// Precompiled for every test executable that does not use widgets (tests/CMakeLists.txt):
// QtTest and QtCore's most used headers, parsed once instead of once per test. Only headers
// from outside the project: a change to ImuDesk's own headers never rebuilds it.
#pragma once
#include <QByteArray>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QObject>
#include <QSignalSpy>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>
#include <QTest>
// After <QTest>: the QTRY_* bounds stretched for a busy machine (the file says why).
#include "../../tests/common/try_bounds.h"
#include "../../tests/common/test_paths.h"
#include <QTimer>
#include <QVariant>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>
