#include "output/pictures_writer.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "app/outputs.hpp"

namespace num::app {

template <int Dim>
void PicturesWriter<Dim>::write(const sph::Storage<Dim>& s, const std::vector<OutputField>&,
                                double t, int index) {
    writePng(c_.path(c_.fileName(index, "png")), renderParticles(s, render_, t));
    pictures_ = index + 1;
}

template <int Dim>
std::string PicturesWriter<Dim>::makeVideo() const {
    if (!onPath("ffmpeg"))
        return "ffmpeg is not installed (./scripts/setup.sh or apt-get install ffmpeg adds it)";
    auto quote = [](const std::string& s) {
        std::string q = "'";
        for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
        return q + "'";
    };
    const int fps = std::clamp(pictures_ / 8, 5, 30);
    const std::string video = c_.path(c_.prefix + ".mp4");
    const std::string log = c_.path("ffmpeg.log");
    // Written under a temporary name and renamed, like every other output.
    // This run's pictures only: a restart that ends before the run it continues leaves that
    // run's later pictures in the folder.
    const std::string cmd = "ffmpeg -y -nostdin -loglevel error -framerate " + std::to_string(fps) +
                            " -i " + quote(c_.path(c_.prefix + "_%04d.png")) + " -frames:v " +
                            std::to_string(pictures_) +
                            " -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -pix_fmt yuv420p -f mp4 " +
                            quote(video + ".tmp") + " >" + quote(log) + " 2>&1";
    const int rc = std::system(cmd.c_str());
    std::ifstream in(log);
    std::string firstLine;
    std::getline(in, firstLine);
    in.close();
    std::remove(log.c_str());
    if (rc != 0 || std::rename((video + ".tmp").c_str(), video.c_str()) != 0) {
        std::remove((video + ".tmp").c_str());
        return "ffmpeg failed" + (firstLine.empty() ? std::string() : ": " + firstLine);
    }
    return "";
}

template <int Dim>
void PicturesWriter<Dim>::finish(bool completed, EndOfRun& end) {
    end.videoWanted = video_;
    if (!video_)
        end.videoNote = "output.video is false";
    else if (!completed)
        end.videoNote = "the run did not complete";
    else if (pictures_ < 2)
        end.videoNote = "fewer than 2 pictures";
    else
        end.videoNote = makeVideo();
    madeVideo_ = end.videoNote.empty();
    if (madeVideo_) end.video = c_.path(c_.prefix + ".mp4");
}

template <int Dim>
std::vector<WrittenFile> PicturesWriter<Dim>::files() const {
    std::vector<WrittenFile> out = {{c_.prefix + "_*.png", "pictures, one per output time (" +
                                                               std::to_string(pictures_) + ")"}};
    if (madeVideo_) out.push_back({c_.prefix + ".mp4", "the pictures as a movie"});
    return out;
}

template class PicturesWriter<2>;
template class PicturesWriter<3>;

}  // namespace num::app
