// The `spira` executable as a script or CI job runs it: --version, --screenshot and exit codes.
#include <iostream>

#include <QFile>
#include <QImage>

#include <QProcess>
#include <QProcessEnvironment>

#include <gtest/gtest.h>

#include "spira/base/version.h"
#include "spira/ui/window/screenshot.h"
#include "support/gui_test_support.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

struct SpiraRun {
  int exitCode = -1;
  QString out;
  QString err;
};

SpiraRun runSpira(const QStringList& args,
                  const QProcessEnvironment& env = QProcessEnvironment::systemEnvironment())
{
  QProcess p;
  p.setProcessEnvironment(env);
  p.start(QStringLiteral(SPIRA_GUI_EXECUTABLE), args);
  SpiraRun r;
  if (!p.waitForFinished(120000)) {
    p.kill();
    p.waitForFinished();
    return r;
  }
  r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
  r.out = QString::fromLocal8Bit(p.readAllStandardOutput());
  r.err = QString::fromLocal8Bit(p.readAllStandardError());
  return r;
}

// Rendered, not blank: many colours in the window and the 3D view not one flat fill.
void expectRenderedWindow(const QString& png)
{
  QImage image(png);
  ASSERT_FALSE(image.isNull()) << png.toStdString();
  EXPECT_EQ(image.size(), QSize(1280, 800));
  EXPECT_GT(distinctColours(image, image.rect()), 500);
  // The middle of the window is the 3D view: the part is there, lit, so it has many shades.
  const QRect middle(image.width() / 2 - 100, image.height() / 2 - 100, 200, 200);
  EXPECT_GT(distinctColours(image, middle), 40);
}

TEST(CommandLine, VersionPrintsTheVersion)
{
  const SpiraRun r = runSpira({"--version"});
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_EQ(r.out.trimmed(), QStringLiteral("spira %1").arg(kVersion));
}

TEST(CommandLine, ScreenshotWritesAPngOfTheWindowWithThePart)
{
  TempDir dir;
  const QString stl = qpath(writeOpenCylinderStl(dir.path()));
  const QString png = qpath(dir / "out.png");
  const SpiraRun r = runSpira({"--screenshot", png, stl});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  expectRenderedWindow(png);
}

TEST(CommandLine, ScreenshotWorksWithQtsOffscreenPlatform)
{
  TempDir dir;
  const QString stl = qpath(writeOpenCylinderStl(dir.path()));
  const QString png = qpath(dir / "offscreen.png");
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert("QT_QPA_PLATFORM", "offscreen");
  const SpiraRun r = runSpira({"--screenshot", png, stl}, env);
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  expectRenderedWindow(png);
}

// High DPI: at a scale factor of 2 the window draws at twice the pixels with the same layout,
// the 3D view filling its place (not a quarter of it) and text at full resolution. Scaled back
// down it matches the normal window.
TEST(CommandLine, ScreenshotAtScaleFactorTwoHasTheSameLayoutAtTwiceThePixels)
{
  TempDir dir;
  const QString stl = qpath(writeOpenCylinderStl(dir.path()));
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert("QT_QPA_PLATFORM", "offscreen");
  const QString normalPng = qpath(dir / "scale1.png");
  ASSERT_EQ(runSpira({"--screenshot", normalPng, stl}, env).exitCode, 0);
  env.insert("QT_SCALE_FACTOR", "2");
  const QString largePng = qpath(dir / "scale2.png");
  const SpiraRun r = runSpira({"--screenshot", largePng, stl}, env);
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  const QImage normal(normalPng), large(largePng);
  ASSERT_EQ(normal.size(), QSize(1280, 800));
  ASSERT_EQ(large.size(), QSize(2560, 1600));
  // The 3D view's middle holds the lit part at both scales.
  const QRect middle(large.width() / 2 - 200, large.height() / 2 - 200, 400, 400);
  EXPECT_GT(distinctColours(large, middle), 40);
  const QImage down = large.scaled(normal.size(), Qt::IgnoreAspectRatio, Qt::SmoothTransformation)
                          .convertToFormat(normal.format());
  // Same layout: the messages' time stamps and text antialiasing differ a little, a moved or
  // quarter-sized view would differ a lot.
  const QRect view(normal.width() / 2 - 150, normal.height() / 2 - 150, 300, 300);
  const double whole = meanDifference(down, normal, normal.rect()),
               inView = meanDifference(down, normal, view);
  std::cout << "[ measure  ] scale 2 scaled down vs scale 1: mean difference " << whole << " (window), "
            << inView << " (3D view)\n";
  EXPECT_LT(whole, 8.0);
  EXPECT_LT(inView, 2.0);
}

TEST(CommandLine, ScreenshotWithoutADisplayStillRenders)
{
  TempDir dir;
  const QString stl = qpath(writeOpenCylinderStl(dir.path()));
  const QString png = qpath(dir / "headless.png");
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.remove("DISPLAY");
  env.remove("WAYLAND_DISPLAY");
  env.remove("QT_QPA_PLATFORM");
  const SpiraRun r = runSpira({"--screenshot", png, stl}, env);
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  expectRenderedWindow(png);
}

TEST(CommandLine, ScreenshotWithoutOpenGLFailsInsteadOfWritingABlankView)
{
  TempDir dir;
  const QString stl = qpath(writeOpenCylinderStl(dir.path()));
  const QString png = qpath(dir / "blank.png");
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.remove("DISPLAY");
  env.remove("WAYLAND_DISPLAY");
  env.insert("QT_QPA_PLATFORM", "offscreen");
  env.insert("SPIRA_NO_XVFB", "1");  // no X server to fall back on: Qt's offscreen platform has no OpenGL
  const SpiraRun r = runSpira({"--screenshot", png, stl}, env);
  EXPECT_EQ(r.exitCode, kExitBadInput);
  EXPECT_TRUE(r.err.contains("spira: no OpenGL context")) << r.err.toStdString();
  EXPECT_FALSE(QFile::exists(png));
}

TEST(CommandLine, BadInputExitsWithThreeAndSaysWhy)
{
  TempDir dir;
  const QString png = qpath(dir / "never.png");
  SpiraRun r = runSpira({"--screenshot", png, qpath(dir / "missing.stl")});
  EXPECT_EQ(r.exitCode, kExitBadInput);
  EXPECT_TRUE(r.err.contains("spira: cannot read")) << r.err.toStdString();

  writeBytes(dir / "broken.stl", std::string(84, '\0') + "\x05\x00\x00\x00");  // claims 5 facets, has none
  r = runSpira({"--screenshot", png, qpath(dir / "broken.stl")});
  EXPECT_EQ(r.exitCode, kExitBadInput);
  EXPECT_TRUE(r.err.contains("spira: ")) << r.err.toStdString();
  EXPECT_TRUE(r.err.contains("hint: ")) << r.err.toStdString();
  EXPECT_FALSE(QFile::exists(png));
}

TEST(CommandLine, UsageErrorsExitWithTwo)
{
  EXPECT_EQ(runSpira({"--screenshot"}).exitCode, kExitUsage);
  EXPECT_EQ(runSpira({"--no-such-option"}).exitCode, kExitUsage);
  const SpiraRun r = runSpira({"--help"});
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_TRUE(r.out.contains("--screenshot IMAGE FILE"));
}

}  // namespace
}  // namespace spira::test
