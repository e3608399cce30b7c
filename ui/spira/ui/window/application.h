#pragma once

class QApplication;

namespace spira::ui {

// Before QApplication exists: VTK's OpenGL widget needs its surface format (core profile,
// depth, stencil) as Qt's default, or the 3D view stays black on some drivers.
void prepareApplication();

// Organisation and application names (where QSettings keeps layout and recent files), version
// and window icon.
void configureApplication(QApplication& app);

// Registers the compiled-in icons (":/spira/..."); safe to call more than once.
void initResources();

}  // namespace spira::ui
