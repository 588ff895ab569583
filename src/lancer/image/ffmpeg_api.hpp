// FFmpeg's functions that the video writer calls, loaded with dlopen the first time a video is
// written rather than linked: FFmpeg's libraries pull in about 130 shared objects (codecs, X11, TLS),
// whose loading and relocation cost every lancer process some 30 ms at start, pictures included.
// Only video_writer.cpp includes this (it needs FFmpeg's headers, present when LANCER_HAVE_FFMPEG).
#pragma once

#if LANCER_HAVE_FFMPEG
#include <string>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

namespace lancer {

// X(library, function): each function the writer calls, from the library (avutil, swscale, avcodec,
// avformat) whose major version the headers name.
#define LANCER_FFMPEG_FUNCTIONS(X)            \
  X(avutil, av_strerror)                      \
  X(avutil, av_log_format_line2)              \
  X(avutil, av_log_set_callback)              \
  X(avutil, av_frame_alloc)                   \
  X(avutil, av_frame_free)                    \
  X(avutil, av_frame_get_buffer)              \
  X(avutil, av_frame_make_writable)           \
  X(avutil, av_malloc)                        \
  X(avutil, av_free)                          \
  X(avutil, av_freep)                         \
  X(avutil, av_dict_set)                      \
  X(avutil, av_dict_free)                     \
  X(avutil, av_d2q)                           \
  X(swscale, sws_getContext)                  \
  X(swscale, sws_freeContext)                 \
  X(swscale, sws_scale)                       \
  X(swscale, sws_setColorspaceDetails)        \
  X(swscale, sws_getCoefficients)             \
  X(avcodec, avcodec_find_encoder)            \
  X(avcodec, avcodec_find_encoder_by_name)    \
  X(avcodec, avcodec_alloc_context3)          \
  X(avcodec, avcodec_free_context)            \
  X(avcodec, avcodec_open2)                   \
  X(avcodec, avcodec_parameters_from_context) \
  X(avcodec, avcodec_send_frame)              \
  X(avcodec, avcodec_receive_packet)          \
  X(avcodec, av_packet_alloc)                 \
  X(avcodec, av_packet_free)                  \
  X(avcodec, av_packet_rescale_ts)            \
  X(avformat, avformat_alloc_output_context2) \
  X(avformat, avformat_free_context)          \
  X(avformat, avformat_new_stream)            \
  X(avformat, avformat_write_header)          \
  X(avformat, av_interleaved_write_frame)     \
  X(avformat, av_write_trailer)               \
  X(avformat, avio_alloc_context)             \
  X(avformat, avio_context_free)              \
  X(avformat, avio_flush)

struct FfmpegApi {
// (`function` names a declaration: it cannot be put in parentheses.)
#define LANCER_FFMPEG_POINTER(library, function) \
  decltype(&::function) function = nullptr;  // NOLINT(bugprone-macro-parentheses)
  LANCER_FFMPEG_FUNCTIONS(LANCER_FFMPEG_POINTER)
#undef LANCER_FFMPEG_POINTER
};

// The functions, loaded once (thread-safe); throws InputError naming `path` (the video being
// written) when a library or a function cannot be loaded, with the package to install.
const FfmpegApi& ffmpegApi(const std::string& path);

}  // namespace lancer
#endif
