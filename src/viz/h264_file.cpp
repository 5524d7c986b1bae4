#include "viz/h264_file.hpp"

#include <cstdint>
#include <stdexcept>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/dict.h>
#include <libavutil/error.h>
#include <libavutil/frame.h>
#include <libavutil/log.h>
#include <libswscale/swscale.h>
}

namespace dynanav {

namespace {

std::string_view trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

std::string avError(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof(text));
  return text;
}

// swscale's SIMD readers may read up to 32 bytes past the last pixel (FFmpeg trac #6763); that
// is harmless only while those bytes lie in the same 4 KiB page as the last pixel.
bool safeToReadPastEnd(const cv::Mat& bgr) {
  constexpr std::uintptr_t kOverread = 32, kPage = 4096;
  const auto end = reinterpret_cast<std::uintptr_t>(bgr.ptr(bgr.rows - 1) + bgr.cols * 3);
  const auto limit = reinterpret_cast<std::uintptr_t>(bgr.datalimit);
  return end + kOverread <= limit || (end - 1) / kPage == (end + kOverread) / kPage;
}

}  // namespace

EncoderOptions parseEncoderOptions(std::string_view text) {
  EncoderOptions out;
  while (!text.empty()) {
    const auto comma = text.find(',');
    const std::string_view item = trimmed(text.substr(0, comma));
    text = comma == std::string_view::npos ? std::string_view{} : text.substr(comma + 1);
    if (item.empty()) continue;
    const auto eq = item.find('=');
    if (eq == std::string_view::npos)
      throw std::invalid_argument("encoder option '" + std::string(item) + "' has no '='");
    const std::string_view key = trimmed(item.substr(0, eq));
    if (key.empty())
      throw std::invalid_argument("encoder option '" + std::string(item) + "' has no name");
    out.emplace_back(std::string(key), std::string(trimmed(item.substr(eq + 1))));
  }
  return out;
}

struct H264File::Impl {
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* to_yuv = nullptr;
  cv::Size size;
  cv::Mat padded;  ///< a copy with slack after the last pixel, when the input has none
  int64_t next_pts = 0;
  bool open = false;  ///< header written, trailer not yet

  ~Impl() {
    sws_freeContext(to_yuv);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
    if (format) {
      if (format->pb) avio_closep(&format->pb);
      avformat_free_context(format);
    }
  }

  // Moves every packet the encoder has ready into the file.
  bool drain() {
    while (true) {
      const int got = avcodec_receive_packet(codec, packet);
      if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return true;
      if (got < 0) return false;
      // Every frame lasts one tick; without a duration the mp4's last sample has none and
      // readers drop it.
      if (packet->duration == 0) packet->duration = 1;
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      if (av_interleaved_write_frame(format, packet) < 0) return false;  // unrefs the packet
    }
  }
};

H264File::H264File(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {
  encoder_name_ = impl_->codec->codec->name;
}

H264File::~H264File() {
  close();
}

std::unique_ptr<H264File> H264File::open(const std::filesystem::path& path, cv::Size size,
                                         double fps, const EncoderOptions& options,
                                         std::string* error) {
  const auto fail = [error](std::string why) {
    if (error) *error = std::move(why);
    return nullptr;
  };
  // x264 prints its banner and settings at FFmpeg's default level "info": keep a run's log to
  // warnings (OpenCV's FFmpeg backend does the same, for the same process-wide setting).
  av_log_set_level(AV_LOG_WARNING);
  auto impl = std::make_unique<Impl>();
  impl->size = {size.width & ~1, size.height & ~1};
  if (impl->size.width <= 0 || impl->size.height <= 0 || fps <= 0)
    return fail("frame size or rate is not positive");
  // libx264 by name (Debian's libavcodec also has libopenh264, which ignores x264's options).
  const AVCodec* encoder = avcodec_find_encoder_by_name("libx264");
  if (!encoder) encoder = avcodec_find_encoder(AV_CODEC_ID_H264);
  if (!encoder) return fail("this FFmpeg has no H.264 encoder");

  if (avformat_alloc_output_context2(&impl->format, nullptr, "mp4", path.c_str()) < 0)
    return fail("FFmpeg has no mp4 muxer");
  impl->format->flags |= AVFMT_FLAG_BITEXACT;  // no library versions in the file: same frames,
                                               // same bytes
  impl->stream = avformat_new_stream(impl->format, nullptr);
  impl->codec = avcodec_alloc_context3(encoder);
  if (!impl->stream || !impl->codec) return fail("out of memory");
  AVCodecContext* c = impl->codec;
  c->width = impl->size.width;
  c->height = impl->size.height;
  c->pix_fmt = AV_PIX_FMT_YUV420P;  // what every player decodes
  c->framerate = av_d2q(fps, 100000);
  c->time_base = av_inv_q(c->framerate);
  if (impl->format->oformat->flags & AVFMT_GLOBALHEADER) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;

  AVDictionary* dict = nullptr;
  for (const auto& [key, value] : options) av_dict_set(&dict, key.c_str(), value.c_str(), 0);
  const int opened = avcodec_open2(c, encoder, &dict);
  std::string unknown;
  for (const AVDictionaryEntry* e = nullptr; (e = av_dict_get(dict, "", e, AV_DICT_IGNORE_SUFFIX));)
    unknown += (unknown.empty() ? "" : ", ") + std::string(e->key);
  av_dict_free(&dict);
  if (opened < 0) return fail(std::string(encoder->name) + " does not open: " + avError(opened));
  if (!unknown.empty()) return fail(std::string(encoder->name) + " has no option " + unknown);

  if (avcodec_parameters_from_context(impl->stream->codecpar, c) < 0)
    return fail("codec parameters");
  impl->stream->time_base = c->time_base;
  impl->frame = av_frame_alloc();
  impl->packet = av_packet_alloc();
  if (!impl->frame || !impl->packet) return fail("out of memory");
  impl->frame->format = c->pix_fmt;
  impl->frame->width = c->width;
  impl->frame->height = c->height;
  if (av_frame_get_buffer(impl->frame, 0) < 0) return fail("out of memory");
  // Same size in and out: swscale takes its unscaled BGR24 -> YUV420P path (BT.601, limited
  // range, as players assume when the stream says nothing).
  impl->to_yuv = sws_getContext(c->width, c->height, AV_PIX_FMT_BGR24, c->width, c->height,
                                AV_PIX_FMT_YUV420P, SWS_BILINEAR, nullptr, nullptr, nullptr);
  if (!impl->to_yuv) return fail("no BGR24 -> YUV420P conversion");

  if (const int e = avio_open(&impl->format->pb, path.c_str(), AVIO_FLAG_WRITE); e < 0)
    return fail("cannot write " + path.string() + ": " + avError(e));
  if (const int e = avformat_write_header(impl->format, nullptr); e < 0)
    return fail("mp4 header: " + avError(e));
  impl->open = true;
  return std::unique_ptr<H264File>(new H264File(std::move(impl)));
}

bool H264File::write(const cv::Mat& bgr) {
  Impl& m = *impl_;
  if (!m.open || bgr.type() != CV_8UC3 || bgr.cols < m.size.width || bgr.rows < m.size.height)
    return false;
  cv::Mat in = bgr(cv::Rect({0, 0}, m.size));
  if (!safeToReadPastEnd(in)) {
    if (m.padded.empty()) m.padded = cv::Mat(m.size.height + 1, m.size.width, CV_8UC3);
    cv::Mat rows = m.padded.rowRange(0, m.size.height);
    in.copyTo(rows);
    in = rows;
  }
  // The encoder may still hold the previous frame's buffer (x264 copies it on input, but the
  // API allows otherwise).
  if (av_frame_make_writable(m.frame) < 0) return false;
  const uint8_t* src[1] = {in.data};
  const int src_stride[1] = {static_cast<int>(in.step)};
  sws_scale(m.to_yuv, src, src_stride, 0, m.size.height, m.frame->data, m.frame->linesize);
  m.frame->pts = m.next_pts++;
  if (avcodec_send_frame(m.codec, m.frame) < 0) return false;
  return m.drain();
}

void H264File::close() {
  if (!impl_ || !impl_->open) return;
  impl_->open = false;
  avcodec_send_frame(impl_->codec, nullptr);  // flush: the encoder may hold frames back
  impl_->drain();
  av_write_trailer(impl_->format);
  avio_closep(&impl_->format->pb);
}

}  // namespace dynanav
