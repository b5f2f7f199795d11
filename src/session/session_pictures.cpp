#include "session_pictures.h"

#include "apcs/raster/painter.h"

namespace apcs {

void write_picture(StepContext& context, const std::string& name, const GraphicsScreen& picture, PngShape shape,
                   const std::string& log_line)
{
    const Expected<std::string> png = encode_png(render_raster(picture), shape);
    if (!png) {
        context.notice = name + ": cannot encode the PNG image: " + png.error().to_string();
        return;
    }
    store_picture(context, name, *png, log_line);
}

void store_picture(StepContext& context, const std::string& name, const std::string& bytes, const std::string& log_line)
{
    if (const Expected<void> written = context.write_file(name, bytes); !written) {
        context.notice = written.error().to_string();
        return;
    }
    context.model.written.add(name);
    context.files.log(log_line);
    context.notice = "wrote " + name;
}

} // namespace apcs
