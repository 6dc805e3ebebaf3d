// The pictures of a run (output.images): a PNG per output time, and at the end of a completed
// run an MP4 of them made by ffmpeg (output.video). Internal to numerics_app.
#pragma once

#include "app/output_writer.hpp"
#include "app/render.hpp"

namespace num::app {

template <int Dim>
class PicturesWriter final : public IWriter<Dim> {
  public:
    /// `video`: make the movie at the end.
    PicturesWriter(const WriterContext& context, const RenderSettings<Dim>& render, bool video)
        : c_(context), render_(render), video_(video) {}

    /// After a restart the pictures are those of the series up to its time.
    void resume(double, const OutputSeries& series) override { pictures_ = int(series.size()); }
    void write(const sph::Storage<Dim>& s, const std::vector<OutputField>& fields, double t,
               int index) override;
    /// The movie when the run completed with at least 2 pictures, else why not.
    void finish(bool completed, EndOfRun& end) override;
    std::vector<WrittenFile> files() const override;

    int pictures() const { return pictures_; }

  private:
    /// Makes <prefix>.mp4 from the pictures with ffmpeg; returns "" or why it could not.
    std::string makeVideo() const;

    WriterContext c_;
    RenderSettings<Dim> render_;
    bool video_;
    int pictures_ = 0;
    bool madeVideo_ = false;
};

}  // namespace num::app
