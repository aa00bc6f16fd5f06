// Build-time tool: renders the hand-drawn SVG icon to a square PNG with Qt's Svg
// module, into a QImage (no application object, no display: the icon has no text).
//   usage: lagrangelab_render_icon ICON.svg SIZE OUT.png
#include <QImage>
#include <QPainter>
#include <QSvgRenderer>

#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fputs("usage: lagrangelab_render_icon ICON.svg SIZE OUT.png\n", stderr);
        return 2;
    }
    QSvgRenderer svg(QString::fromLocal8Bit(argv[1]));
    const int size = std::atoi(argv[2]);
    if (!svg.isValid() || size < 8 || size > 1024) {
        std::fprintf(stderr, "error: cannot render %s at size %s\n", argv[1], argv[2]);
        return 2;
    }
    QImage image(size, size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    svg.render(&painter);
    painter.end();
    const std::string out = argv[3];
    const std::string partial = out + ".part.png";
    if (!image.save(QString::fromStdString(partial), "PNG") || std::rename(partial.c_str(), out.c_str()) != 0) {
        std::fprintf(stderr, "error: cannot write %s\n", out.c_str());
        return 1;
    }
    return 0;
}
