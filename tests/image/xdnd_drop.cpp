// Drops a file on an X11 window the way a file manager does, by the XDND protocol
// (freedesktop.org's Drag-and-Drop Protocol for the X Window System, version 5): enter,
// position, wait for the window's status, drop, hand over the file's URI as text/uri-list when
// the window asks for the selection, wait for finished. For testing the viewer's drop handling.
//   xdnd_drop WINDOW_ID FILE
#include <X11/Xatom.h>
#include <X11/Xlib.h>

#include <time.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

Display* display = nullptr;
Window source = 0, target = 0;

Atom atom(const char* name) { return XInternAtom(display, name, False); }

void send(const char* type, long l1, long l2, long l3, long l4) {
  XEvent e{};
  e.xclient.type = ClientMessage;
  e.xclient.window = target;
  e.xclient.message_type = atom(type);
  e.xclient.format = 32;
  e.xclient.data.l[0] = long(source);
  e.xclient.data.l[1] = l1;
  e.xclient.data.l[2] = l2;
  e.xclient.data.l[3] = l3;
  e.xclient.data.l[4] = l4;
  XSendEvent(display, target, False, NoEventMask, &e);
  XFlush(display);
}

// Waits up to 10 s for a client message of this type, answering selection requests meanwhile.
bool waitFor(const char* type, const std::string& uriList, XEvent& out) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (std::chrono::steady_clock::now() < until) {
    if (!XPending(display)) {
      struct timespec pause = {0, 10000000};
      nanosleep(&pause, nullptr);
      continue;
    }
    XEvent e;
    XNextEvent(display, &e);
    if (e.type == SelectionRequest) {
      const XSelectionRequestEvent& r = e.xselectionrequest;
      XEvent reply{};
      reply.xselection.type = SelectionNotify;
      reply.xselection.requestor = r.requestor;
      reply.xselection.selection = r.selection;
      reply.xselection.target = r.target;
      reply.xselection.time = r.time;
      reply.xselection.property = None;
      if (r.target == atom("text/uri-list")) {
        XChangeProperty(display, r.requestor, r.property, r.target, 8, PropModeReplace,
                        reinterpret_cast<const unsigned char*>(uriList.data()), int(uriList.size()));
        reply.xselection.property = r.property;
      }
      XSendEvent(display, r.requestor, False, NoEventMask, &reply);
      XFlush(display);
    } else if (e.type == ClientMessage && e.xclient.message_type == atom(type)) {
      out = e;
      return true;
    }
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: xdnd_drop WINDOW_ID FILE\n");
    return 2;
  }
  display = XOpenDisplay(nullptr);
  if (!display) {
    std::fprintf(stderr, "xdnd_drop: cannot open the display\n");
    return 1;
  }
  target = Window(std::strtoul(argv[1], nullptr, 0));
  char* path = realpath(argv[2], nullptr);
  if (!path) {
    std::fprintf(stderr, "xdnd_drop: %s: no such file\n", argv[2]);
    return 1;
  }
  const std::string uriList = std::string("file://") + path + "\r\n";
  std::free(path);

  // The target must say it takes drops, and which protocol version.
  Atom type = None;
  int format = 0;
  unsigned long count = 0, after = 0;
  unsigned char* data = nullptr;
  if (XGetWindowProperty(display, target, atom("XdndAware"), 0, 1, False, XA_ATOM, &type, &format, &count, &after,
                         &data) != Success ||
      count == 0) {
    std::fprintf(stderr, "xdnd_drop: window %s is not XdndAware\n", argv[1]);
    return 1;
  }
  const long version = std::min(5L, long(*reinterpret_cast<Atom*>(data)));
  XFree(data);

  source = XCreateSimpleWindow(display, DefaultRootWindow(display), 0, 0, 1, 1, 0, 0, 0);
  XSetSelectionOwner(display, atom("XdndSelection"), source, CurrentTime);

  // Over the middle of the window.
  XWindowAttributes attributes;
  XGetWindowAttributes(display, target, &attributes);
  int x = 0, y = 0;
  Window child;
  XTranslateCoordinates(display, target, DefaultRootWindow(display), attributes.width / 2, attributes.height / 2, &x,
                        &y, &child);
  send("XdndEnter", version << 24, long(atom("text/uri-list")), 0, 0);
  send("XdndPosition", 0, (long(x) << 16) | long(y), CurrentTime, long(atom("XdndActionCopy")));
  XEvent status;
  if (!waitFor("XdndStatus", uriList, status)) {
    std::fprintf(stderr, "xdnd_drop: no XdndStatus from the window\n");
    return 1;
  }
  if (!(status.xclient.data.l[1] & 1)) {
    std::fprintf(stderr, "xdnd_drop: the window refuses the drop\n");
    send("XdndLeave", 0, 0, 0, 0);
    return 1;
  }
  send("XdndDrop", 0, CurrentTime, 0, 0);
  XEvent finished;
  if (!waitFor("XdndFinished", uriList, finished)) {
    std::fprintf(stderr, "xdnd_drop: no XdndFinished from the window\n");
    return 1;
  }
  std::printf("dropped %s", uriList.c_str());
  XCloseDisplay(display);
  return 0;
}
