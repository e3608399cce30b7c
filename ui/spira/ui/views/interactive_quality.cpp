#include "spira/ui/views/interactive_quality.h"

#include <QTimer>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkInteractorObserver.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

#include "spira/ui/views/scene_view.h"

namespace spira::ui {

namespace {

void onEvent(vtkObject*, unsigned long event, void* client, void*)
{
  auto* self = static_cast<InteractiveQuality*>(client);
  if (event == vtkCommand::StartInteractionEvent)
    self->interactionStarted();
  else
    self->interactionEnded();
}

}  // namespace

InteractiveQuality::InteractiveQuality(SceneView* view, int settleMs) : QObject(view), view_(view)
{
  settle_ = new QTimer(this);
  settle_->setSingleShot(true);
  settle_->setInterval(settleMs);
  connect(settle_, &QTimer::timeout, this, &InteractiveQuality::restore);
  renderer_ = view->renderer();
  window_ = renderer_ ? renderer_->GetRenderWindow() : nullptr;
  style_ = window_ && window_->GetInteractor() ? window_->GetInteractor()->GetInteractorStyle() : nullptr;
  if (vtkInteractorObserver* style = style_) {
    vtkNew<vtkCallbackCommand> command;
    command->SetCallback(onEvent);
    command->SetClientData(this);
    startTag_ = style->AddObserver(vtkCommand::StartInteractionEvent, command);
    endTag_ = style->AddObserver(vtkCommand::EndInteractionEvent, command);
  }
}

InteractiveQuality::~InteractiveQuality()
{
  if (vtkInteractorObserver* style = style_) {
    style->RemoveObserver(startTag_);
    style->RemoveObserver(endTag_);
  }
}

void InteractiveQuality::interactionStarted()
{
  settle_->stop();
  vtkRenderWindow* w = window_;
  if (!w || !renderer_ || fast_) return;
  samples_ = w->GetMultiSamples();
  w->SetMultiSamples(0);
  widths_.clear();
  vtkActorCollection* actors = renderer_->GetActors();
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor()) {
    const double width = a->GetProperty()->GetLineWidth();
    if (width > 1.0) {
      widths_.emplace_back(a, width);
      a->GetProperty()->SetLineWidth(1.0);
    }
  }
  fast_ = true;
}

void InteractiveQuality::interactionEnded()
{
  // A wheel step is a whole interaction: wait until the camera stays still.
  if (fast_ && holds_ == 0) settle_->start();
}

void InteractiveQuality::fastFrame()
{
  interactionStarted();
  interactionEnded();
  view_->scheduleRender();
}

void InteractiveQuality::hold()
{
  ++holds_;
  interactionStarted();
}

void InteractiveQuality::release()
{
  if (holds_ == 0) return;
  if (--holds_ == 0) interactionEnded();
}

void InteractiveQuality::restore()
{
  if (!fast_ || holds_ > 0) return;
  applyFullQuality();
  view_->scheduleRender();
}

void InteractiveQuality::fullQualityNow()
{
  settle_->stop();
  applyFullQuality();
}

void InteractiveQuality::applyFullQuality()
{
  vtkRenderWindow* w = window_;
  if (!w || !fast_) return;
  w->SetMultiSamples(samples_);
  for (const auto& [actor, width] : widths_)
    if (actor) actor->GetProperty()->SetLineWidth(width);
  widths_.clear();
  fast_ = false;
}

}  // namespace spira::ui
