// SkinnedCharacter [FILE] OUTDIR [FRAMES]: renders the animation of a skinned character (default
// assimp-testmodels' X/BCN_Epileptic.X) to OUTDIR/frame_NNNN.png, FRAMES frames (default 48) over
// its animation, each frame the four blend modes of vtkProbeDeformerLCT side by side (Polar,
// MatrixLog, Linear = LBS, DualQuaternion). The scene is Examples/SkinnedCharacterScene.h, the
// same one Testing/Cxx/TestSkinnedCharacter.cxx compares with its baseline.
//
// Needs an X display (run it under `xvfb-run -a`). Exit codes: 0 written, 1 error, 2 usage,
// 125 no DISPLAY.
#include "SkinnedCharacterScene.h"

#include "vtkPNGWriter.h"
#include "vtkWindowToImageFilter.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  if (argc < 2 || argc > 4 || std::string(argv[1]) == "--help")
  {
    std::cerr << "usage: SkinnedCharacter [FILE] OUTDIR [FRAMES]\n"
                 "  Renders a skinned character's animation with the four blend modes of\n"
                 "  vtkProbeDeformerLCT side by side to OUTDIR/frame_NNNN.png.\n";
    return 2;
  }
  // Two arguments are FILE OUTDIR unless the second is a frame count (OUTDIR FRAMES).
  const auto isCount = [](const char* text) {
    char* end = nullptr;
    std::strtol(text, &end, 10);
    return *text && !*end;
  };
  const bool fileGiven = argc == 4 || (argc == 3 && !isCount(argv[2]));
  const std::string file = fileGiven ? argv[1] : "/usr/share/assimp/models/X/BCN_Epileptic.X";
  const std::string outdir = fileGiven ? argv[2] : argv[1];
  const char* countText = argc == 4 ? argv[3] : (argc == 3 && !fileGiven ? argv[2] : nullptr);
  char* end = nullptr;
  const long frames = countText ? std::strtol(countText, &end, 10) : 48;
  if ((countText && (!*countText || *end)) || frames < 1 || frames > 100000)
  {
    std::cerr << "SkinnedCharacter: FRAMES must be an integer in [1, 100000]\n";
    return 2;
  }
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    std::cerr << "SkinnedCharacter: DISPLAY is not set (run under xvfb-run -a)\n";
    return 125;
  }
  std::error_code ec;
  std::filesystem::create_directories(outdir, ec);
  if (ec)
  {
    std::cerr << "SkinnedCharacter: cannot create " << outdir << ": " << ec.message() << "\n";
    return 1;
  }
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(960, 360);
  SkinnedCharacterScene::Scene scene;
  if (!SkinnedCharacterScene::Build(window, file, scene))
  {
    std::cerr << "SkinnedCharacter: " << file << " could not be read (see the error above)\n";
    return 1;
  }
  const double t0 = scene.reader->GetStartTime(), t1 = scene.reader->GetEndTime();
  for (long f = 0; f < frames; ++f)
  {
    const double t = frames > 1 ? t0 + (t1 - t0) * f / (frames - 1) : t0;
    if (!scene.SetTime(t))
    {
      std::cerr << "SkinnedCharacter: frame " << f << " (t = " << t << " s) failed\n";
      return 1;
    }
    scene.Frame();
    window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->ReadFrontBufferOff();
    vtkNew<vtkPNGWriter> writer;
    char name[32];
    std::snprintf(name, sizeof(name), "/frame_%04ld.png", f);
    const std::string path = outdir + name;
    const std::string part = path + ".part";
    writer->SetFileName(part.c_str());
    writer->SetInputConnection(grab->GetOutputPort());
    writer->Write();
    std::filesystem::rename(part, path, ec);
    if (writer->GetErrorCode() || ec)
    {
      std::cerr << "SkinnedCharacter: cannot write " << path << "\n";
      std::filesystem::remove(part, ec);
      return 1;
    }
    std::cout << "frame " << f + 1 << "/" << frames << " t = " << t << " s -> " << path << "\n";
  }
  return 0;
}
