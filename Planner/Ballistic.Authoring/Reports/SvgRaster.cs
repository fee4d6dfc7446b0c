using SkiaSharp;
using Svg.Skia;

namespace Ballistic.Authoring.Reports;

/// <summary>
/// Our SVG pictures as PNG images, drawn by Svg.Skia (SkiaSharp): the same picture as the SVG, its text included,
/// so that a PNG viewer sees the title and legend the SVG has. Deterministic for the same SVG on the same machine.
/// </summary>
internal static class SvgRaster
{
    /// <summary>The PNG of <paramref name="svg"/> (an SVG document with a width and height), on white, at its own size in pixels.</summary>
    /// <exception cref="InvalidOperationException">The document draws nothing (not SVG).</exception>
    public static byte[] ToPng(string svg)
    {
        using var document = new SKSvg();
        SKPicture picture = document.FromSvg(svg) ?? throw new InvalidOperationException("the SVG document draws nothing");
        SKRect bounds = picture.CullRect;
        var info = new SKImageInfo(Math.Max(1, (int)MathF.Ceiling(bounds.Width)), Math.Max(1, (int)MathF.Ceiling(bounds.Height)), SKColorType.Rgba8888, SKAlphaType.Premul);
        using SKSurface surface = SKSurface.Create(info) ?? throw new InvalidOperationException($"no {info.Width} × {info.Height} drawing surface");
        surface.Canvas.Clear(SKColors.White);
        surface.Canvas.DrawPicture(picture);
        using SKImage image = surface.Snapshot();
        using SKData data = image.Encode(SKEncodedImageFormat.Png, 100);
        return data.ToArray();
    }
}
