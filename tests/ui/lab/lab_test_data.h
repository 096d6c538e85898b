#pragma once

// Test input for the lab tabs: the CLI's files (tests/data/lab_*.csv).

#include <QString>

namespace probecycle::ui::lab_test {

inline QString lab_data(const char* name) {
    return QStringLiteral(PROBECYCLE_LAB_DATA_DIR "/") + QLatin1String(name);
}

}  // namespace probecycle::ui::lab_test
