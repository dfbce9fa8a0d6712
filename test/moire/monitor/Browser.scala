package moire.monitor

import java.time.Duration
import org.openqa.selenium.{By, OutputType, TakesScreenshot, WebDriver, WebElement}
import org.openqa.selenium.chrome.{ChromeDriver, ChromeDriverService, ChromeOptions}
import org.openqa.selenium.logging.{LogType, LoggingPreferences}
import org.openqa.selenium.support.ui.WebDriverWait
import scala.jdk.CollectionConverters._

/** Debian's headless Chromium through /usr/bin/chromedriver, with a fresh profile; the flags keep Chromium from
  * reaching for the network (on a closed network it stalls without them). Screenshots go to target/browser/.
  */
final class Browser private (val driver: ChromeDriver, profile: os.Path) extends AutoCloseable {
  def go(url: String): Unit = driver.get(url)
  def find(id: String): WebElement = driver.findElement(By.id(id))
  /** Waits (polling, never a fixed sleep) until `cond` holds; fails with `what` after `seconds`. */
  def waitFor(what: String, seconds: Double)(cond: => Boolean): Double = {
    val t0 = System.nanoTime()
    try new WebDriverWait(driver, Duration.ofMillis((seconds * 1000).toLong), Duration.ofMillis(100))
      .until((_: WebDriver) => java.lang.Boolean.valueOf(try cond catch { case _: org.openqa.selenium.WebDriverException => false }))
    catch { case _: org.openqa.selenium.TimeoutException => org.scalatest.Assertions.fail(s"not within $seconds s: $what") }
    (System.nanoTime() - t0) / 1e9
  }
  def js(script: String): AnyRef = driver.executeScript(script)
  /** An element's text and an attribute, read in one script (the page redraws its tables several times a second). */
  def text(id: String): String = String.valueOf(js(s"const e = document.getElementById('$id'); return e ? e.textContent : null"))
  def attr(id: String, name: String): String = String.valueOf(js(s"const e = document.getElementById('$id'); return e ? e.getAttribute('$name') : null"))
  /** Console messages at level SEVERE (errors) since the last call. */
  def consoleErrors: Seq[String] = driver.manage().logs().get(LogType.BROWSER).getAll.asScala.toSeq
    .filter(_.getLevel == java.util.logging.Level.SEVERE).map(_.getMessage)
  def screenshot(name: String): os.Path = {
    val f = Browser.shots / s"$name.png"
    os.write.over(f, driver.asInstanceOf[TakesScreenshot].getScreenshotAs(OutputType.BYTES), createFolders = true)
    f
  }
  def close(): Unit = { try driver.quit() finally os.remove.all(profile) }
}

object Browser {
  val chromium = os.Path("/usr/bin/chromium"); val chromedriver = os.Path("/usr/bin/chromedriver")
  val shots: os.Path = os.pwd / "target" / "browser"

  /** Runs `body` with a browser; cancels the test when Chromium or its driver is not installed. */
  def apply[T](width: Int = 1400, height: Int = 1100)(body: Browser => T): T = {
    if (!os.isFile(chromium) || !os.isFile(chromedriver))
      org.scalatest.Assertions.cancel("chromium and chromium-driver are not installed (apt-get install chromium chromium-driver)")
    val profile = os.temp.dir(prefix = "moire-chromium")
    val o = new ChromeOptions()
    o.setBinary(chromium.toIO)
    o.addArguments("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
      "--disable-component-update", "--disable-sync", "--disable-dev-shm-usage", s"--user-data-dir=$profile", s"--window-size=$width,$height")
    val logs = new LoggingPreferences(); logs.enable(LogType.BROWSER, java.util.logging.Level.ALL)
    o.setCapability("goog:loggingPrefs", logs)
    val service = new ChromeDriverService.Builder().usingDriverExecutable(chromedriver.toIO).usingAnyFreePort().build()
    val b = new Browser(new ChromeDriver(service, o), profile)
    try body(b) finally b.close()
  }
}
