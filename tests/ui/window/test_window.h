#pragma once

// A window as the tests drive it: offscreen, 1280x800, shown, without
// settings (nothing read or saved) and without dialogs (errors in
// last_error()).

#include <QCoreApplication>
#include <memory>

#include "ui/window/main_window.h"

namespace probecycle::ui {

inline std::unique_ptr<MainWindow> make_window() {
    MainWindowOptions options;
    options.persistent = false;
    options.show_dialogs = false;
    auto window = std::make_unique<MainWindow>(options);
    window->resize(1280, 800);
    window->show();
    QCoreApplication::processEvents();
    return window;
}

}  // namespace probecycle::ui
