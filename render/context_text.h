#pragma once

#include <string>

#include <vtkContextItem.h>
#include <vtkNew.h>
#include <vtkTextProperty.h>

namespace sedem::render {

// A line of text in a chart's scene, centred on a point (pixels, origin bottom left). Drawn
// through the scene's painter like the charts themselves, so vtkSVGExporter writes it as SVG
// text; a vtkTextActor beside the scene is in the picture but not in the SVG.
class ContextText : public vtkContextItem {
 public:
  static ContextText* New();
  vtkTypeMacro(ContextText, vtkContextItem)

      void Set(const std::string& text, float x, float y, int size, bool bold);
  bool Paint(vtkContext2D* painter) override;

 protected:
  ContextText() = default;
  ~ContextText() override = default;

 private:
  ContextText(const ContextText&) = delete;
  void operator=(const ContextText&) = delete;

  std::string text_;
  float x_ = 0, y_ = 0;
  vtkNew<vtkTextProperty> prop_;
};

}  // namespace sedem::render
