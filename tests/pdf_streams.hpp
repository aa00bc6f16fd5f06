#pragma once
// The streams of a PDF written by QPdfWriter, inflated, in file order: each page's
// drawing (BT … ET text objects, one "x y Td <glyph> Tj" per glyph), the font subsets and
// their character maps. Streams that are not deflated (the XMP metadata, which holds the
// creation date) are left out, so two PDFs of the same pages compare equal.
#include <QByteArray>
#include <QList>

namespace ll::test {

inline QList<QByteArray> inflatedStreams(const QByteArray& pdf) {
    QList<QByteArray> streams;
    for (qsizetype at = 0; (at = pdf.indexOf("stream", at)) >= 0;) {
        qsizetype start = at + 6;
        if (pdf.mid(start, 2) == "\r\n") {
            start += 2;
        } else if (start < pdf.size() && pdf.at(start) == '\n') {
            start += 1;
        } else {  // the end of "endstream"
            at = start;
            continue;
        }
        const qsizetype end = pdf.indexOf("endstream", start);
        if (end < 0) break;
        at = end + 9;
        if (quint8(pdf.at(start)) != 0x78) continue;  // not zlib
        QByteArray sized("\x00\x10\x00\x00", 4);      // qUncompress's size hint; it grows as needed
        sized += pdf.mid(start, end - start);
        streams.push_back(qUncompress(sized));
    }
    return streams;
}

}  // namespace ll::test
