#pragma once

#include <functional>

#include <QString>

class QActionGroup;
class QMenu;
class QObject;
class vtkRenderer;

namespace spira::ui {

enum class Theme { System, Light, Dark };

QString themeKey(Theme t);               // "system", "light", "dark" (settings value)
Theme themeFromKey(const QString& key);  // unknown: System
QString themeLabel(Theme t);             // "&Light", ...

// Applies `t` to the whole application: Light and Dark use the Fusion style with a fixed
// palette; System puts back the style and palette the application started with. Remembered as
// the current theme (not saved: see saveTheme).
void applyTheme(Theme t);
Theme currentTheme();
// The theme saved in QSettings ("view/theme"), System when none.
Theme savedTheme();
void saveTheme(Theme t);
// Whether the palette in use is a dark one (System may be dark too).
bool paletteIsDark();

// The 3D view's background for the palette in use: a blue-grey gradient, darker with a dark
// palette but always light enough that the view's dark labels and colour-bar text stay legible.
void applySceneBackground(vtkRenderer* renderer);

// Adds View > Theme (System, Light, Dark; exclusive, checked as saved) to `menu`. Choosing one
// applies and saves it, then calls `changed`.
QActionGroup* addThemeMenu(QMenu* menu, QObject* owner, std::function<void()> changed = {});

}  // namespace spira::ui
