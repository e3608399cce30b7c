#include "spira/ui/panels/param_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QLocale>
#include <QPainter>
#include <QPolygonF>
#include <QSpinBox>
#include <QStyle>
#include <QToolButton>

#include "spira/base/units.h"

namespace spira::ui {

namespace {

// The shown unit as a spin-box suffix: "deg" reads better as a degree sign.
QString unitSuffix(const std::string& unit)
{
  if (unit.empty()) return {};
  if (unit == "deg") return QStringLiteral("°");
  return QLatin1Char(' ') + QString::fromStdString(unit);
}

// A step of about a hundredth of the range, rounded to a power of ten, and enough decimals to
// show it and the default.
double stepFor(double lo, double hi)
{
  const double span = hi - lo;
  if (!(span > 0.0) || !std::isfinite(span)) return 0.1;
  return std::pow(10.0, std::floor(std::log10(span / 100.0)));
}

int decimalsFor(double step, double def)
{
  int d = std::max(1, static_cast<int>(-std::floor(std::log10(step))) + 1);
  for (int k = 0; k < 4 && std::abs(def * std::pow(10.0, d) - std::round(def * std::pow(10.0, d))) > 1e-6;
       ++k)
    ++d;
  return std::clamp(d, 1, 4);
}

// "0 = ..." or "0 uses ..." in the tooltip: zero stands for an automatic value.
bool zeroMeansAutomatic(const ParamDef& def)
{
  return def.min && *def.min == 0.0 &&
         (def.tooltip.find("0 =") != std::string::npos || def.tooltip.find("0 uses") != std::string::npos ||
          def.tooltip.find("Empty:") != std::string::npos);
}

// A "turn back" arrow (an open circle running anticlockwise into an arrowhead), drawn rather than
// taken from the style or a font, which may not have one.
QIcon resetIcon(const QColor& colour)
{
  QPixmap pm(32, 32);
  pm.fill(Qt::transparent);
  QPainter p(&pm);
  p.setRenderHint(QPainter::Antialiasing);
  p.setPen(QPen(colour, 2.6, Qt::SolidLine, Qt::RoundCap));
  const QPointF centre(16.0, 17.0);
  const double radius = 9.5;
  // From the top, round the left, the bottom and the right side back up (Qt: degrees * 16,
  // anticlockwise), leaving a gap at the top for the arrowhead.
  constexpr double start = 105.0, span = 300.0;
  p.drawArc(QRectF(centre.x() - radius, centre.y() - radius, 2 * radius, 2 * radius), int(start * 16),
            int(span * 16));
  const double a = degToRad(start + span);
  const QPointF end = centre + QPointF(radius * std::cos(a), -radius * std::sin(a));
  const QPointF along(-std::sin(a), -std::cos(a));  // direction of travel on screen (y down)
  const QPointF across(along.y(), -along.x());
  p.setPen(Qt::NoPen);
  p.setBrush(colour);
  const QPointF head[3] = {end + 7.0 * along, end - 1.0 * along + 5.5 * across,
                           end - 1.0 * along - 5.5 * across};
  p.drawPolygon(head, 3);
  return QIcon(pm);
}

double asDouble(const ParamValue& v)
{
  if (const auto* d = std::get_if<double>(&v)) return *d;
  if (const auto* i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
  return 0.0;
}

}  // namespace

ParamField::ParamField(ParamDef def, QWidget* parent) : QWidget(parent), def_(std::move(def))
{
  setObjectName(QString::fromStdString("param_" + def_.key));
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(4);
  switch (def_.type) {
    case ParamType::Double:
    case ParamType::Int:
      buildNumber();
      break;
    case ParamType::Choice:
      buildChoice();
      break;
    case ParamType::Bool:
      check_ = new QCheckBox(this);
      editor_ = check_;
      connect(check_, &QCheckBox::toggled, this, &ParamField::emitEdited);
      break;
    case ParamType::Path:
      buildPath();
      break;
    case ParamType::String:
      line_ = new QLineEdit(this);
      editor_ = line_;
      connect(line_, &QLineEdit::editingFinished, this, &ParamField::emitEdited);
      break;
  }
  const QString tip = QString::fromStdString(def_.tooltip);
  editor_->setToolTip(tip);
  editor_->setObjectName(QStringLiteral("editor"));
  layout->addWidget(editor_, 1);
  if (browse_) layout->addWidget(browse_);

  reset_ = new QToolButton(this);
  reset_->setObjectName(QStringLiteral("reset"));
  reset_->setIcon(resetIcon(palette().color(QPalette::Highlight)));
  reset_->setAutoRaise(true);
  reset_->setToolTip(tr("Reset to the default: %1").arg(displayText(def_, def_.defaultValue)));
  reset_->setEnabled(false);
  connect(reset_, &QToolButton::clicked, this, &ParamField::resetRequested);
  layout->addWidget(reset_);
  setValue(def_.defaultValue, true);
}

void ParamField::buildNumber()
{
  const QString suffix = unitSuffix(def_.unit);
  if (def_.type == ParamType::Int) {
    intBox_ = new QSpinBox(this);
    const double lo = def_.min.value_or(std::numeric_limits<int>::min());
    const double hi = def_.max.value_or(std::numeric_limits<int>::max());
    intBox_->setRange(static_cast<int>(std::max<double>(lo, std::numeric_limits<int>::min())),
                      static_cast<int>(std::min<double>(hi, std::numeric_limits<int>::max())));
    intBox_->setSuffix(suffix);
    intBox_->setKeyboardTracking(false);
    intBox_->setAccelerated(true);
    editor_ = intBox_;
    connect(intBox_, QOverload<int>::of(&QSpinBox::valueChanged), this, &ParamField::emitEdited);
    return;
  }
  doubleBox_ = new QDoubleSpinBox(this);
  const double lo = def_.min.value_or(-1e9), hi = def_.max.value_or(1e9);
  const double step = stepFor(lo, hi);
  doubleBox_->setDecimals(decimalsFor(step, asDouble(def_.defaultValue)));
  doubleBox_->setRange(lo, hi);
  doubleBox_->setSingleStep(step);
  doubleBox_->setSuffix(suffix);
  doubleBox_->setKeyboardTracking(false);
  doubleBox_->setAccelerated(true);
  if (zeroMeansAutomatic(def_)) doubleBox_->setSpecialValueText(tr("auto"));
  editor_ = doubleBox_;
  connect(doubleBox_, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, &ParamField::emitEdited);
}

void ParamField::buildChoice()
{
  combo_ = new QComboBox(this);
  for (const std::string& c : def_.choices)
    combo_->addItem(QString::fromStdString(c), QString::fromStdString(c));
  editor_ = combo_;
  connect(combo_, QOverload<int>::of(&QComboBox::activated), this, &ParamField::emitEdited);
}

void ParamField::buildPath()
{
  line_ = new QLineEdit(this);
  line_->setClearButtonEnabled(true);
  editor_ = line_;
  connect(line_, &QLineEdit::editingFinished, this, &ParamField::emitEdited);
  browse_ = new QToolButton(this);
  browse_->setObjectName(QStringLiteral("browse"));
  browse_->setText(tr("Browse..."));
  browse_->setToolTip(tr("Choose the file"));
  connect(browse_, &QToolButton::clicked, this, &ParamField::browse);
}

void ParamField::setValue(const ParamValue& value, bool isDefault)
{
  updating_ = true;
  isDefault_ = isDefault;
  if (doubleBox_) {
    doubleBox_->setValue(asDouble(value));
  } else if (intBox_) {
    intBox_->setValue(static_cast<int>(asDouble(value)));
  } else if (combo_) {
    const auto* s = std::get_if<std::string>(&value);
    combo_->setCurrentIndex(s ? combo_->findData(QString::fromStdString(*s)) : -1);
  } else if (check_) {
    const auto* b = std::get_if<bool>(&value);
    check_->setChecked(b && *b);
  } else if (line_) {
    const auto* s = std::get_if<std::string>(&value);
    line_->setText(s ? QString::fromStdString(*s) : QString());
  }
  reset_->setEnabled(!isDefault);
  updating_ = false;
}

ParamValue ParamField::value() const
{
  if (doubleBox_) return doubleBox_->value();
  if (intBox_) return std::int64_t{intBox_->value()};
  if (combo_) return combo_->currentData().toString().toStdString();
  if (check_) return check_->isChecked();
  return line_->text().toStdString();
}

void ParamField::emitEdited()
{
  if (updating_) return;
  emit edited(value());
}

void ParamField::browse()
{
  const QString start = line_->text().isEmpty() ? QString() : QFileInfo(line_->text()).absolutePath();
  const QString file =
      QFileDialog::getOpenFileName(this, tr("Choose %1").arg(QString::fromStdString(def_.label)), start,
                                   tr("CSV tables (*.csv);;All files (*)"));
  if (file.isEmpty()) return;
  line_->setText(file);
  emitEdited();
}

QString ParamField::displayText(const ParamDef& def, const ParamValue& value)
{
  if (const auto* b = std::get_if<bool>(&value)) return *b ? tr("on") : tr("off");
  if (const auto* s = std::get_if<std::string>(&value))
    return s->empty() ? tr("none") : QString::fromStdString(*s);
  const double v = asDouble(value);
  if (v == 0.0 && zeroMeansAutomatic(def)) return tr("auto");
  return QLocale().toString(v, 'g', 6) + unitSuffix(def.unit);
}

}  // namespace spira::ui
