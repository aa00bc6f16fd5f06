#pragma once
// A tinted background behind an entry of the derivation, in every view that shows it (the
// typeset page, the text, the teach panel): the entry a student picked, or the entries a
// picked link feeds, in that link's colour.
#include <QColor>

namespace ll::ui {

struct EntryMark {
    int step = 0, item = 0;  // indices into the document's steps and the step's items (−1: the pose results)
    int row = -1, col = -1;  // one entry of the item's matrix; −1: the whole item
    QColor colour;
};

}  // namespace ll::ui
