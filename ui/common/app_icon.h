#pragma once

// The application icon, drawn rather than shipped as an image so it is sharp
// at every size without an SVG plugin.

#include <QIcon>

namespace probecycle::ui {

QIcon app_icon();

}  // namespace probecycle::ui
