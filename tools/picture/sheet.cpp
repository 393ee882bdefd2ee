#include "sheet.h"

#include <algorithm>

#include "canvas.h"
#include "hedge/error.h"
#include "text.h"

namespace hedge::picture {

Image contact_sheet(const std::vector<Panel>& panels, int columns, Rgb background) {
  if (panels.empty()) throw InvalidInputError("a contact sheet needs at least one picture");
  int cell_w = 0, cell_h = 0;
  for (const Panel& p : panels) {
    cell_w = std::max(cell_w, p.image.width());
    cell_h = std::max(cell_h, p.image.height());
  }
  const int n = int(panels.size());
  const int cols = columns <= 0 ? n : std::min(columns, n);
  const int rows = (n + cols - 1) / cols;
  const double px = std::clamp(cell_w / 28.0, 11.0, 18.0);
  const int caption_h = int(px * 2);
  const std::int64_t sheet_w = std::int64_t(cell_w) * cols, sheet_h = std::int64_t(cell_h + caption_h) * rows;
  if (sheet_w > kMaxSide || sheet_h > kMaxSide) check_size(kMaxSide + 1, 1, "a contact sheet");
  Image sheet(int(sheet_w), int(sheet_h), background);
  ImageCanvas canvas(sheet);
  const Font& font = Font::standard();
  for (int i = 0; i < n; ++i) {
    const int x = (i % cols) * cell_w, y = (i / cols) * (cell_h + caption_h);
    const Panel& p = panels[std::size_t(i)];
    sheet.paste(p.image, x + (cell_w - p.image.width()) / 2, y + (cell_h - p.image.height()) / 2);
    std::string caption = p.caption;
    while (caption.size() > 3 && font.width(caption, px) > cell_w - 8) caption = caption.substr(0, caption.size() - 4) + "...";
    canvas.text({x + cell_w / 2.0, y + cell_h + caption_h / 2.0}, px, caption, Rgb{30, 30, 30});
  }
  return sheet;
}

}  // namespace hedge::picture
