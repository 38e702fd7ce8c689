// Precompiled for the widget tests (tests/ui/, tests/CMakeLists.txt): the test headers plus
// the widgets they drive most.
#pragma once
#include "test_pch.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTableView>
#include <QWidget>
